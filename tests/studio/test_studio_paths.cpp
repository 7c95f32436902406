// apps/studio/static_files.hpp: a request path leads to a file under its folder or is
// refused by form (403) or absence (404); the folder check is on components, not strings.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/studio/static_files.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using tessera_studio::resolve_under;

class StudioPaths : public tessera::test::TempDirTest {
protected:
    void SetUp() override {
        TempDirTest::SetUp();
        fs::create_directories(dir_ / "root" / "sub");
        fs::create_directories(dir_ / "rootx");
        write("root/sub/a.json", "{}");
        write("rootx/b.json", "{}");
        base_ = fs::canonical(dir_ / "root");
    }
    fs::path base_;
};

TEST_F(StudioPaths, AFileUnderTheFolderIsServed) {
    const auto r = resolve_under(base_, "sub/a.json", {".json"});
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.path, base_ / "sub" / "a.json");
    EXPECT_EQ(resolve_under(base_, "sub/./a.json").status, 200);
}

TEST_F(StudioPaths, PathsThatLeaveOrHideAreRefusedByForm) {
    for (const char* path : {"../rootx/b.json", "sub/../../rootx/b.json", "/etc/passwd", "sub\\a.json",
                             "%2e%2e/rootx/b.json", ".hidden.json", "sub/.git/config", ""})
        EXPECT_EQ(resolve_under(base_, path).status, 403) << path;
}

TEST_F(StudioPaths, ASiblingFolderWithTheSamePrefixIsNotInside) {
    EXPECT_FALSE(tessera_studio::is_within(base_, fs::canonical(dir_ / "rootx")));
    EXPECT_TRUE(tessera_studio::is_within(base_, base_ / "sub"));
    fs::create_directory_symlink(dir_ / "rootx", dir_ / "root" / "link");
    EXPECT_EQ(resolve_under(base_, "link/b.json").status, 403);
}

TEST_F(StudioPaths, MissingFilesAndOtherExtensionsAre404) {
    EXPECT_EQ(resolve_under(base_, "sub/none.json").status, 404);
    EXPECT_EQ(resolve_under(base_, "sub").status, 404);
    EXPECT_EQ(resolve_under(base_, "sub/a.json", {".csv"}).status, 404);
    EXPECT_EQ(resolve_under(base_, "sub/A.JSON", {".json"}).status,
              404);  // case-sensitive file system: absent
}

TEST_F(StudioPaths, TheDefaultAppFolderPrefersTheInstalledOne) {
    fs::create_directories(dir_ / "prefix" / "bin");
    fs::create_directories(dir_ / "src" / "web" / "dist");
    const fs::path exe = dir_ / "prefix" / "bin" / "tessera";
    EXPECT_EQ(tessera_studio::default_app_dir(exe, (dir_ / "src/web/dist").string()),
              fs::canonical(dir_ / "src/web/dist"));
    fs::create_directories(dir_ / "prefix" / "share" / "tessera" / "studio");
    EXPECT_EQ(tessera_studio::default_app_dir(exe, (dir_ / "src/web/dist").string()),
              fs::canonical(dir_ / "prefix/share/tessera/studio"));
    EXPECT_TRUE(tessera_studio::default_app_dir(dir_ / "nowhere" / "tessera", "").empty());
}

}  // namespace
