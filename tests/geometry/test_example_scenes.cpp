// The example scenes of examples/scenes/ (docs/examples.md) stay loadable: every exemplar
// validates, its types' meshes resolve relative to the file, and every element is rebuilt
// (rigid ones exactly: the posed reference layout lands on the samples).
#include <gtest/gtest.h>

#include <filesystem>

#include "tessera/tessera.hpp"

using namespace tessera;
namespace fs = std::filesystem;

TEST(GeometryExampleScenes, EveryExemplarBuildsItsScene) {
    const fs::path dir = fs::path(TESSERA_SOURCE_DIR) / "examples" / "scenes";
    int exemplars = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".json" || name.find("_field") != std::string::npos ||
            name.find("_disk") != std::string::npos)
            continue;
        SCOPED_TRACE(name);
        const Exemplar ex = load(entry.path().string());
        ++exemplars;
        bool any_mesh = false;
        for (const auto& t : ex.types) any_mesh = any_mesh || !t.mesh.empty();
        EXPECT_TRUE(any_mesh);
        const Scene scene = build_scene(ex);
        ASSERT_EQ(scene.instances.size(), ex.elements.size());
        for (const auto& inst : scene.instances)
            if (inst.instanced) { EXPECT_LT(inst.fit_error, 1e-3); }
    }
    EXPECT_EQ(exemplars, 7);
}
