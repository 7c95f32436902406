// Tests of pcf_model_to_json / pcf_model_from_json: exact round trip, and strict reading
// with errors that name the source and the key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "analysis_test_data.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

namespace {

PcfModel sample_model() {
    Exemplar ex = test::three_classes({std::vector<std::string>{"c"}, std::nullopt, std::vector<std::string>{}});
    for (size_t i = 0; i < ex.elements.size(); ++i) ex.elements[i].radius = 0.05 + 0.01 * (i % 7);
    PcfAnalysisSettings s;
    s.sigma = 0.2;
    s.step = 0.25;
    s.extent = 3.0;
    return analyze_distribution(ex, s);
}

std::string error_of(const std::string& text) {
    try {
        pcf_model_from_json(text, "model.json");
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        return e.what();
    }
    return "no error";
}

// The sample model's JSON with `edit` applied.
std::string edited(const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = nlohmann::json::parse(pcf_model_to_json(sample_model()));
    edit(j);
    return j.dump();
}

}  // namespace

TEST(PcfModelJson, RoundTripIsExact) {
    const PcfModel m = sample_model();
    const std::string text = pcf_model_to_json(m);
    const PcfModel back = pcf_model_from_json(text, "model.json");
    EXPECT_EQ(back.classes, m.classes);
    EXPECT_EQ(back.parents, m.parents);
    EXPECT_EQ(back.order, m.order);
    EXPECT_EQ(back.counts, m.counts);
    EXPECT_EQ(back.radii, m.radii);
    EXPECT_EQ(back.x, m.x);
    EXPECT_EQ(back.disks, m.disks);
    EXPECT_EQ(back.r_max, m.r_max);
    EXPECT_EQ(back.area, m.area);
    EXPECT_EQ(back.settings.sigma, m.settings.sigma);
    EXPECT_EQ(back.settings.step, m.settings.step);
    EXPECT_EQ(back.settings.extent, m.settings.extent);
    ASSERT_EQ(back.pcfs.size(), m.pcfs.size());
    for (size_t q = 0; q < m.pcfs.size(); ++q) {
        EXPECT_EQ(back.pcfs[q].parent, m.pcfs[q].parent);
        EXPECT_EQ(back.pcfs[q].child, m.pcfs[q].child);
        EXPECT_EQ(back.pcfs[q].mean, m.pcfs[q].mean);
        EXPECT_EQ(back.pcfs[q].lower, m.pcfs[q].lower);
        EXPECT_EQ(back.pcfs[q].upper, m.pcfs[q].upper);
    }
    ASSERT_EQ(back.separations.size(), m.separations.size());
    for (size_t q = 0; q < m.separations.size(); ++q) {
        EXPECT_EQ(back.separations[q].a, m.separations[q].a);
        EXPECT_EQ(back.separations[q].b, m.separations[q].b);
        EXPECT_EQ(back.separations[q].x, m.separations[q].x);
    }
    EXPECT_EQ(pcf_model_to_json(back), text);
    // A measurement with the read model gives what the original gives.
    EXPECT_EQ(measure_distribution(back, test::three_classes())[0].mean,
              measure_distribution(m, test::three_classes())[0].mean);
}

TEST(PcfModelJson, VersionOneHasNoSeparations) {
    // Models written before separations existed read as before, without them.
    const std::string text = edited([](nlohmann::json& j) {
        j["version"] = 1;
        j.erase("separations");
        j.erase("sparse");
    });
    const PcfModel m = pcf_model_from_json(text, "old.json");
    EXPECT_TRUE(m.separations.empty());
    EXPECT_EQ(m.pcfs.size(), sample_model().pcfs.size());
    EXPECT_NE(error_of(edited([](nlohmann::json& j) {
                  j["version"] = 1;
                  j.erase("sparse");
              })).find("unknown key 'separations'"),
              std::string::npos);
    EXPECT_NE(error_of(edited([](nlohmann::json& j) { j["version"] = 2; })).find("unknown key 'sparse'"),
              std::string::npos);
}

TEST(PcfModelJson, PointModelRoundTrips) {
    const PcfModel m = analyze_distribution(test::poisson_points(50, 5.0, 2));
    const PcfModel back = pcf_model_from_json(pcf_model_to_json(m), "m.json");
    EXPECT_FALSE(back.disks);
    EXPECT_EQ(back.x, m.x);
    EXPECT_EQ(back.pcfs[0].mean, m.pcfs[0].mean);
}

TEST(PcfModelJson, StrictReading) {
    const struct {
        std::function<void(nlohmann::json&)> edit;
        std::vector<std::string> say;
    } cases[] = {
        {[](nlohmann::json& j) { j["colour"] = 1; }, {"unknown key 'colour'"}},
        {[](nlohmann::json& j) { j.erase("r_max"); }, {"missing \"r_max\""}},
        {[](nlohmann::json& j) { j["version"] = 4; }, {"version", "4"}},
        {[](nlohmann::json& j) { j.erase("separations"); }, {"missing \"separations\""}},
        {[](nlohmann::json& j) { j["separations"] = nlohmann::json::array(); }, {"separations", "missing the pair 'b', 'c'"}},
        {[](nlohmann::json& j) { j["separations"][0]["x"] = -1; }, {"separations[0].x", ">= 0"}},
        {[](nlohmann::json& j) { j["separations"][0]["a"] = "c"; }, {"separations[0]", "before b"}},
        {[](nlohmann::json& j) { j["separations"].push_back({{"a", "a"}, {"b", "b"}, {"x", 1.0}}); },
         {"separations[1]", "have a PCF between them"}},
        {[](nlohmann::json& j) { j["format"] = "tessera"; }, {"format"}},
        {[](nlohmann::json& j) { j["settings"]["sigma"] = 0; }, {"settings.sigma"}},
        {[](nlohmann::json& j) { j["r_max"] = -1; }, {"r_max", "> 0"}},
        {[](nlohmann::json& j) { j["classes"][1]["count"] = 0; }, {"classes[1].count"}},
        {[](nlohmann::json& j) { j["classes"][0]["radii"].erase(0); }, {"classes[0].radii"}},
        {[](nlohmann::json& j) { j["classes"][1]["depends_on"] = {"rock"}; }, {"classes", "'rock'", "'b'"}},
        {[](nlohmann::json& j) { j["classes"][2]["depends_on"] = {"a"}; }, {"cycle", "'a'", "'c'"}},
        {[](nlohmann::json& j) { j["order"] = {"a", "b", "c"}; }, {"order[0]", "before its parent 'c'"}},
        {[](nlohmann::json& j) { j["x"].erase(0); }, {"x", "numbers"}},
        {[](nlohmann::json& j) { j["pcfs"][1]["mean"].erase(0); }, {"pcfs[1].mean"}},
        {[](nlohmann::json& j) { j["pcfs"][1]["upper"][3] = "big"; }, {"pcfs[1].upper[3]", "number"}},
        {[](nlohmann::json& j) { j["pcfs"].erase(0); }, {"pcfs", "missing the PCF"}},
        {[](nlohmann::json& j) { j["pcfs"][0]["child"] = "rock"; }, {"pcfs[0].child", "rock"}},
    };
    for (const auto& c : cases) {
        const std::string e = error_of(edited(c.edit));
        EXPECT_EQ(e.rfind("model.json: ", 0), 0u) << e;
        for (const std::string& s : c.say) EXPECT_NE(e.find(s), std::string::npos) << "'" << s << "' not in: " << e;
    }
    EXPECT_NE(error_of("{\"format\": ").find("invalid JSON"), std::string::npos);
    EXPECT_NE(error_of("[1, 2]").find("JSON object"), std::string::npos);
}
