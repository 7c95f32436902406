// Operations and jobs: a small paint answers at once with the elements it appended, a large
// one runs as a job to done; a second op while one
// runs is 409; a cancelled fill ends "cancelled" with the canvas as it was; progress streams
// as server-sent events until the job ends; a session file reloads to the same arrangement;
// exports come back in their formats.
#include <chrono>
#include <string>
#include <thread>

#include "studio/studio_fixture.hpp"

namespace {

using Json = nlohmann::json;

class StudioJobs : public tessera::test::StudioFixture {
protected:
    // A canvas with one small paint stroke, run in the request (paint_estimate.hpp): its answer
    // carries the elements it appended.
    std::string painted_session(Json* answer = nullptr) {
        const std::string id = sticks_session("box:0,0,40,20");
        int status = 0;
        const Json painted = post(
            "/api/sessions/" + id + "/ops",
            {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{4, 10}, {36, 10}}}, {"width", 4}}, &status);
        EXPECT_EQ(status, 200) << painted.dump();
        if (answer) *answer = painted;
        return id;
    }
};

TEST_F(StudioJobs, ASmallPaintAnswersWithTheElementsItAddedAsTheSessionShowsThem) {
    Json painted;
    const std::string id = painted_session(&painted);
    int status = 0;
    const Json session = get("/api/sessions/" + id, &status);
    ASSERT_EQ(status, 200);
    EXPECT_GT(session["arrangement"]["elements"].size(), 10u);
    const Json& changes = painted["changes"];
    ASSERT_TRUE(changes.is_object()) << painted.dump();
    EXPECT_EQ(changes["first_element"], 0);
    EXPECT_EQ(changes["arrangement"]["elements"], session["arrangement"]["elements"]);
    EXPECT_EQ(changes["arrangement"]["types"], session["arrangement"]["types"]);
    EXPECT_EQ(changes["directions"], session["directions"]);
    EXPECT_EQ(painted["report"]["added"], session["arrangement"]["elements"].size());
    // A second stroke: only its own elements come back, after the first stroke's.
    const Json second = post("/api/sessions/" + id + "/ops",
                             {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{4, 3}, {36, 3}}}, {"width", 3}},
                             &status);
    ASSERT_EQ(status, 200) << second.dump();
    const Json after = get("/api/sessions/" + id)["arrangement"]["elements"];
    const size_t first = session["arrangement"]["elements"].size();
    ASSERT_EQ(second["changes"]["first_element"], first);
    ASSERT_EQ(after.size(), first + second["changes"]["arrangement"]["elements"].size());
    for (size_t k = first; k < after.size(); ++k)
        EXPECT_EQ(after[k], second["changes"]["arrangement"]["elements"][k - first]);
    EXPECT_EQ(session.value("ops", 0), 1);
    EXPECT_TRUE(session["job"].is_null());
    EXPECT_EQ(session["directions"].size(), session["exemplars"].size());
    const Json report =
        post("/api/sessions/" + id + "/ops", {{"op", "direction"}, {"stroke", {{0, 0}, {40, 20}}}}, &status);
    EXPECT_EQ(status, 200) << report.dump();
    EXPECT_TRUE(report.contains("report"));
    post("/api/sessions/" + id + "/ops", {{"op", "paint"}, {"palette", "nope"}, {"stroke", {{0, 0}, {1, 1}}}},
         &status);
    EXPECT_EQ(status, 400);
    post("/api/sessions/" + id + "/ops", {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{0, 0, 1}}}},
         &status);
    EXPECT_EQ(status, 400);  // z on a 2D canvas
}

TEST_F(StudioJobs, ALargePaintRunsAsAJobToDone) {
    const std::string id = sticks_session("box:0,0,200,200");
    int status = 0;
    const Json started = post("/api/sessions/" + id + "/ops",
                              {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{10, 100}, {190, 100}}}, {"width", 60}},
                              &status);
    ASSERT_EQ(status, 202) << started.dump();
    const Json end = wait_for_job(started.value("job", ""));
    EXPECT_EQ(end.value("state", ""), "done") << end.dump();
    EXPECT_GT(get("/api/sessions/" + id)["arrangement"]["elements"].size(), 400u);
}

TEST_F(StudioJobs, ACancelledFillEndsCancelledWithTheCanvasAsItWas) {
    const std::string id = sticks_session("box:0,0,400,400");
    const Json before = get("/api/sessions/" + id)["arrangement"];
    int status = 0;
    const Json started =
        post("/api/sessions/" + id + "/ops", {{"op", "fill"}, {"palette", {"sticks"}}}, &status);
    ASSERT_EQ(status, 202) << started.dump();
    const std::string job = started.value("job", "");
    post("/api/sessions/" + id + "/ops", {{"op", "optimize"}, {"iterations", 1}}, &status);
    EXPECT_EQ(status, 409);  // one job at a time per session
    post("/api/sessions/" + id + "/ops", {{"op", "erase"}, {"stroke", {{0, 0}, {10, 10}}}}, &status);
    EXPECT_EQ(status, 409);
    del("/api/jobs/" + job, &status);
    EXPECT_EQ(status, 202);
    const auto cancelled_at = std::chrono::steady_clock::now();
    const Json end = wait_for_job(job, 30);
    EXPECT_EQ(end.value("state", ""), "cancelled") << end.dump();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - cancelled_at).count(), 10.0);
    const Json session = get("/api/sessions/" + id);
    EXPECT_EQ(session["arrangement"], before);
    EXPECT_EQ(session.value("ops", -1), 0);
    EXPECT_TRUE(session["job"].is_null());
    // The session is free again.
    post("/api/sessions/" + id + "/ops", {{"op", "direction"}, {"stroke", {{0, 0}, {10, 10}}}}, &status);
    EXPECT_EQ(status, 200);
}

TEST_F(StudioJobs, ProgressStreamsAsServerSentEventsUntilTheJobEnds) {
    const std::string id = painted_session();
    int status = 0;
    const Json started =
        post("/api/sessions/" + id + "/ops", {{"op", "optimize"}, {"iterations", 2}}, &status);
    ASSERT_EQ(status, 202) << started.dump();
    std::string stream;
    const auto res = client()->Get(("/api/jobs/" + started.value("job", "") + "/events").c_str(),
                                   [&](const char* data, size_t n) {
                                       stream.append(data, n);
                                       return stream.size() < (1u << 24);
                                   });
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    EXPECT_EQ(res->get_header_value("Content-Type"), "text/event-stream");
    const size_t last = stream.rfind("event: job\ndata: ");
    ASSERT_NE(last, std::string::npos) << stream;
    const std::string data = stream.substr(last + 17, stream.find('\n', last + 17) - last - 17);
    EXPECT_EQ(Json::parse(data).value("state", ""), "done") << data;
}

TEST_F(StudioJobs, ASessionFileReloadsToTheSameArrangement) {
    const std::string id = painted_session();
    int status = 0;
    post("/api/sessions/" + id + "/ops", {{"op", "erase"}, {"stroke", {{20, 0}, {20, 20}}}, {"width", 2}},
         &status);
    EXPECT_EQ(status, 200);
    const Json file = get("/api/sessions/" + id + "/file", &status);
    ASSERT_EQ(status, 200);
    EXPECT_EQ(file.value("format", ""), "tessera-brush");
    EXPECT_EQ(file.value("canvas", ""), "box:0,0,40,20");
    EXPECT_EQ(file["palette"].value("sticks", ""), "examples/sticks_2d.json");
    EXPECT_EQ(file["ops"].size(), 2u);
    const Json loaded = post("/api/sessions/load", file, &status);
    ASSERT_EQ(status, 201) << loaded.dump();
    const Json end = wait_for_job(loaded.value("job", ""));
    EXPECT_EQ(end.value("state", ""), "done") << end.dump();
    EXPECT_EQ(get("/api/sessions/" + loaded.value("id", ""))["arrangement"],
              get("/api/sessions/" + id)["arrangement"]);
    Json bad = file;
    bad["options"]["nonsense"] = 1;
    EXPECT_NE(post("/api/sessions/load", bad, &status).value("error", "").find("options.nonsense"),
              std::string::npos);
    EXPECT_EQ(status, 400);
    bad = file;
    bad["ops"][0]["stroke"] = "here";
    EXPECT_NE(post("/api/sessions/load", bad, &status).value("error", "").find("ops[0].stroke"),
              std::string::npos);
    EXPECT_EQ(status, 400);
}

TEST_F(StudioJobs, ASessionFileUnderTheRootLoadsWithItsPalettePathsFromItsFolder) {
    std::filesystem::create_directories(root_ / "examples" / "brush");
    const Json file = {
        {"format", "tessera-brush"},
        {"version", 1},
        {"canvas", "box:0,0,40,20"},
        {"palette", {{"sticks", "../sticks_2d.json"}}},
        {"ops", {{{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{4, 10}, {36, 10}}}, {"width", 4}}}}};
    write("root/examples/brush/small.json", file.dump());
    int status = 0;
    const Json loaded = post("/api/sessions/load", {{"path", "examples/brush/small.json"}}, &status);
    ASSERT_EQ(status, 201) << loaded.dump();
    EXPECT_EQ(wait_for_job(loaded.value("job", "")).value("state", ""), "done");
    const Json saved = get("/api/sessions/" + loaded.value("id", "") + "/file");
    EXPECT_EQ(saved["palette"].value("sticks", ""), "examples/sticks_2d.json");  // now relative to the root
    EXPECT_EQ(get("/api/sessions/" + loaded.value("id", ""))["arrangement"],
              get("/api/sessions/" + painted_session())["arrangement"]);
    Json outside = file;
    outside["palette"]["sticks"] = "../../../secret.json";
    write("root/examples/brush/outside.json", outside.dump());
    post("/api/sessions/load", {{"path", "examples/brush/outside.json"}}, &status);
    EXPECT_EQ(status, 403);
    post("/api/sessions/load", {{"path", "../secret.json"}}, &status);
    EXPECT_EQ(status, 403);
    EXPECT_EQ(get("/api/sessions")["sessions"].size(), 2u);  // nothing of the refused files stayed
}

TEST_F(StudioJobs, ExportsComeBackInTheirFormats) {
    const std::string id = painted_session();
    auto c = client();
    const auto exported = [&](const std::string& format) {
        return c->Post(("/api/sessions/" + id + "/export").c_str(), Json{{"format", format}}.dump(),
                       "application/json");
    };
    auto png = exported("png");
    ASSERT_TRUE(png);
    EXPECT_EQ(png->status, 200);
    EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(png->body.substr(1, 3), "PNG");
    auto glb = exported("glb");
    ASSERT_TRUE(glb);
    EXPECT_EQ(glb->status, 200) << glb->body.substr(0, 200);
    EXPECT_EQ(glb->body.substr(0, 4), "glTF");
    auto json = exported("json");
    ASSERT_TRUE(json);
    EXPECT_EQ(Json::parse(json->body).value("format", ""), "tessera");
    auto bad = exported("exe");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->status, 400);
}

TEST_F(StudioJobs, ADeletedSessionIsGone) {
    const std::string id = sticks_session("box:0,0,20,20");
    int status = 0;
    del("/api/sessions/" + id, &status);
    EXPECT_EQ(status, 200);
    get("/api/sessions/" + id, &status);
    EXPECT_EQ(status, 404);
    del("/api/sessions/" + id, &status);
    EXPECT_EQ(status, 404);
}

}  // namespace
