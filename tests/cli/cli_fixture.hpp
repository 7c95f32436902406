// Shared by the end-to-end tests of the `tessera` command-line tool (tests/cli/): a
// fixture that runs the built binary (TESSERA_CLI) in a fresh temporary directory and
// captures its exit code, stdout and stderr, and small helpers to read what it wrote.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace tessera_cli_test {

namespace fs = std::filesystem;

inline const std::string examples = std::string(TESSERA_SOURCE_DIR) + "/examples/";

inline std::string example(const std::string& name) {
    return examples + name;
}

inline std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Result {
    int code = -1;
    std::string out, err;
};

// A fresh work directory for the files a test makes, and a separate one for the
// captured stdout/stderr so that the work directory holds only what tessera wrote.
class CliFixture : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "tessera_cli_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        root_ = pattern;
        fs::create_directories(root_ / "work");
        fs::create_directories(root_ / "capture");
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(root_, ignored);
    }

    std::string path(const std::string& name) const { return (root_ / "work" / name).string(); }

    void write(const std::string& name, const std::string& content) const {
        std::ofstream(path(name), std::ios::binary) << content;
    }

    std::set<std::string> work_files() const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(root_ / "work"))
            names.insert(entry.path().filename().string());
        return names;
    }

    // Runs `tessera <args>` (args already quoted as needed) in the shell.
    Result run(const std::string& args) const {
        const fs::path out = root_ / "capture" / "stdout", err = root_ / "capture" / "stderr";
        const std::string command = "'" + std::string(TESSERA_CLI) + "' " + args + " >'" + out.string() +
                                    "' 2>'" + err.string() + "'";
        const int status = std::system(command.c_str());
        Result r;
        r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = read_text(out);
        r.err = read_text(err);
        return r;
    }

    fs::path root_;
};

inline std::string q(const std::string& s) {
    return "'" + s + "'";
}

inline int line_count(const std::string& text) {
    int n = 0;
    for (char c : text) n += c == '\n';
    return n;
}

inline void expect_count_near(size_t actual, double expected) {
    EXPECT_GT(static_cast<double>(actual), 0.75 * expected);
    EXPECT_LT(static_cast<double>(actual), 1.25 * expected);
}

inline bool is_png(const std::string& path) {
    const std::string bytes = read_text(path);
    return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

}  // namespace tessera_cli_test
