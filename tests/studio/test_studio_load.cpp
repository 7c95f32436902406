// Several clients at once: 200 concurrent requests over 20 connections all answered 200
// within a bound, and two sessions driven from two threads ending exactly as each does alone.
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "studio/studio_fixture.hpp"

namespace {

using Json = nlohmann::json;

class StudioLoad : public tessera::test::StudioFixture {
protected:
    // Runs a session's ops to their end; its arrangement.
    Json drive(const std::string& id, const std::vector<Json>& ops) const {
        for (const Json& op : ops) {
            int status = 0;
            const Json answer = post("/api/sessions/" + id + "/ops", op, &status);
            if (status == 202) {
                const Json end = wait_for_job(answer.value("job", ""));
                EXPECT_EQ(end.value("state", ""), "done") << end.dump();
            } else {
                EXPECT_EQ(status, 200) << answer.dump();
            }
        }
        return get("/api/sessions/" + id)["arrangement"];
    }
};

TEST_F(StudioLoad, TwoHundredConcurrentRequestsAreAllAnswered) {
    int status = 0;
    const std::string id = post("/api/sessions", {{"canvas", "box:0,0,40,20"}}, &status).value("id", "");
    ASSERT_EQ(status, 201);
    constexpr int threads = 20, per_thread = 10;
    std::atomic<int> ok{0}, other{0};
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            auto c = client();
            for (int k = 0; k < per_thread; ++k) {
                const std::string path = (t + k) % 2 ? "/api/palette" : "/api/sessions/" + id;
                const auto res = c->Get(path.c_str());
                (res && res->status == 200 ? ok : other)++;
            }
        });
    for (std::thread& t : pool) t.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(ok.load(), threads * per_thread);
    EXPECT_EQ(other.load(), 0);
    EXPECT_LT(seconds, 60.0);
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioLoad, TwoSessionsDrivenAtOnceDoNotAffectEachOther) {
    const std::vector<Json> ops_a = {
        {{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{4, 10}, {36, 10}}}, {"width", 4}},
        {{"op", "erase"}, {"stroke", {{20, 0}, {20, 20}}}, {"width", 3}}};
    const std::vector<Json> ops_b = {{{"op", "paint"}, {"palette", "sticks"}, {"stroke", {{5, 5}, {25, 25}}}},
                                     {{"op", "direction"}, {"stroke", {{0, 30}, {30, 30}}}}};
    Json together_a, together_b;
    const std::string a = sticks_session("box:0,0,40,20"), b = sticks_session("box:0,0,30,30");
    std::thread ta([&] { together_a = drive(a, ops_a); });
    std::thread tb([&] { together_b = drive(b, ops_b); });
    ta.join();
    tb.join();
    ASSERT_FALSE(together_a["elements"].empty());
    ASSERT_FALSE(together_b["elements"].empty());
    EXPECT_EQ(together_a, drive(sticks_session("box:0,0,40,20"), ops_a));
    EXPECT_EQ(together_b, drive(sticks_session("box:0,0,30,30"), ops_b));
}

}  // namespace
