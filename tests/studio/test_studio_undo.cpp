// Undo and redo kept by the server (apps/studio/session_history.hpp): a step is one gesture
// (the operations of one group), undo puts the canvas and the operations back as they were
// before it without replaying the session, redo puts the step back, a new operation drops
// the redo steps, palette entries added since a step stay usable after its undo, a job's
// operation is a step too, and a loaded session file has nothing to undo.
#include <string>

#include "studio/studio_fixture.hpp"

namespace {

using Json = nlohmann::json;

class StudioUndo : public tessera::test::StudioFixture {
protected:
    // POSTs an op of `group` (none when negative) and expects `status`.
    Json op(const std::string& id, Json body, int group, int expected = 200) {
        if (group >= 0) body["group"] = group;
        int status = 0;
        const Json answer = post("/api/sessions/" + id + "/ops", body, &status);
        EXPECT_EQ(status, expected) << answer.dump();
        return answer;
    }
    static Json paint(double y, double x0, double x1) {
        return {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{x0, y}, {x1, y}}}, {"width", 3}};
    }
    // What a user sees of the session: its elements, their directions and the ops count.
    Json seen(const std::string& id) {
        const Json s = get("/api/sessions/" + id);
        return {{"elements", s["arrangement"]["elements"]}, {"directions", s["directions"]}, {"ops", s["ops"]}};
    }
    int step(const std::string& id, const std::string& which, Json* answer = nullptr) {
        int status = 0;
        const Json a = post("/api/sessions/" + id + "/" + which, Json::object(), &status);
        if (answer) *answer = a;
        return status;
    }
};

TEST_F(StudioUndo, UndoAndRedoGoBackOneGestureAtATime) {
    const std::string id = sticks_session("box:0,0,40,20");
    const Json empty = seen(id);
    op(id, paint(10, 4, 20), 7);  // one stroke sent in two parts: one step
    op(id, paint(10, 20, 36), 7);
    const Json stroke = seen(id);
    op(id, {{"op", "direction"}, {"stroke", {{0, 0}, {40, 20}}}}, -1);  // a step of its own
    const Json directed = seen(id);
    op(id, paint(4, 4, 36), 8);
    const Json last = seen(id);
    ASSERT_GT(last["elements"].size(), stroke["elements"].size());
    EXPECT_EQ(get("/api/sessions/" + id).value("undo", -1), 3);

    Json answer;
    EXPECT_EQ(step(id, "undo", &answer), 200);
    EXPECT_EQ(answer.value("undo", -1), 2);
    EXPECT_EQ(answer.value("redo", -1), 1);
    EXPECT_EQ(seen(id), directed);
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_EQ(seen(id), stroke);
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_EQ(seen(id), empty);
    EXPECT_EQ(step(id, "undo", &answer), 409);
    EXPECT_NE(answer.value("error", "").find("nothing to undo"), std::string::npos) << answer.dump();
    for (const Json& want : {stroke, directed, last}) {
        EXPECT_EQ(step(id, "redo"), 200);
        EXPECT_EQ(seen(id), want);
    }
    EXPECT_EQ(step(id, "redo"), 409);
    // The session file holds the ops of the state shown.
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_EQ(get("/api/sessions/" + id + "/file")["ops"].size(), 3u);
    // A new operation drops what could be redone.
    op(id, {{"op", "erase"}, {"stroke", {{20, 0}, {20, 20}}}, {"width", 2}}, 9);
    EXPECT_EQ(step(id, "redo"), 409);
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_EQ(seen(id), directed);
}

TEST_F(StudioUndo, APaletteEntryAddedAfterAStepStaysUsableAfterItsUndo) {
    const std::string id = sticks_session("box:0,0,40,20");
    op(id, paint(10, 4, 36), 1);
    int status = 0;
    post("/api/sessions/" + id + "/palette", {{"name", "dots"}, {"path", "examples/two_class_2d.json"}}, &status);
    ASSERT_EQ(status, 201);
    op(id, {{"op", "paint"}, {"palette", "dots"}, {"stroke", {{4, 3}, {36, 3}}}, {"width", 3}}, 2);
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_EQ(step(id, "undo"), 200);
    EXPECT_TRUE(seen(id)["elements"].empty());
    op(id, {{"op", "paint"}, {"palette", "dots"}, {"stroke", {{4, 3}, {36, 3}}}, {"width", 3}}, 3);
    EXPECT_FALSE(seen(id)["elements"].empty());
    EXPECT_EQ(get("/api/sessions/" + id)["palette"].size(), 2u);
}

TEST_F(StudioUndo, AJobsOperationIsOneStepAndUndoWaitsForNoJob) {
    const std::string id = sticks_session("box:0,0,40,20");
    op(id, paint(10, 4, 36), 1);
    const Json painted = seen(id);
    const Json started = op(id, {{"op", "fill"}, {"palette", {"sticks"}}}, 2, 202);
    const std::string job = started.value("job", "");
    Json answer;
    const int during = step(id, "undo", &answer);  // 409 while the fill runs, unless it ended already
    if (during == 409 && answer.value("error", "").find("busy") != std::string::npos) {
        EXPECT_EQ(wait_for_job(job).value("state", ""), "done");
        EXPECT_EQ(step(id, "undo"), 200);
    } else {
        EXPECT_EQ(during, 200) << answer.dump();
    }
    EXPECT_EQ(seen(id), painted);
}

TEST_F(StudioUndo, ALoadedSessionHasNothingToUndoAndABadGroupIsRefused) {
    const std::string id = sticks_session("box:0,0,40,20");
    op(id, paint(10, 4, 36), 1);
    int status = 0;
    const Json loaded = post("/api/sessions/load", get("/api/sessions/" + id + "/file"), &status);
    ASSERT_EQ(status, 201) << loaded.dump();
    wait_for_job(loaded.value("job", ""));
    EXPECT_EQ(step(loaded.value("id", ""), "undo"), 409);
    Json bad = paint(4, 4, 36);
    bad["group"] = "x";
    const Json refused = op(id, bad, -1, 400);
    EXPECT_NE(refused.value("error", "").find("group"), std::string::npos) << refused.dump();
    bad["group"] = -2;
    op(id, bad, -1, 400);
    EXPECT_EQ(step("nope", "undo"), 404);
}

}  // namespace
