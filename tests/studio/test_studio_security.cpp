// The studio server refuses what it must without falling over: bodies over the cap (413),
// paths out of its two folders in every encoding (403/404), malformed JSON and unknown
// options (400 naming them), unknown routes (404) and methods (405), and requests of other
// sites (403); after each, it still answers.
#include <string>

#include "studio/studio_fixture.hpp"

namespace {

using tessera::test::StudioFixture;
using StudioServer = StudioFixture;
using Json = nlohmann::json;

TEST_F(StudioServer, AnOversizedBodyIs413AndTheServerStaysUp) {
    const std::string big(max_body + 1, ' ');
    auto res = client()->Post("/api/sessions", big, "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 413);
    EXPECT_TRUE(server_answers());
    // Chunked bodies carry no length for httplib to check: the server caps them as it reads.
    std::string request =
        "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n";
    const std::string chunk(64 * 1024, 'x');
    char size[32];
    std::snprintf(size, sizeof size, "%zx\r\n", chunk.size());
    for (size_t sent = 0; sent <= max_body; sent += chunk.size()) request += size + chunk + "\r\n";
    request += "0\r\n\r\n";
    EXPECT_EQ(raw_status(request), 413);
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioServer, RootFilesAreServedReadOnlyAndOnlyUnderTheRoot) {
    std::string response;
    EXPECT_EQ(raw_get("/api/files?path=examples/sticks_2d.json", &response), 200);
    EXPECT_NE(response.find("\"format\""), std::string::npos);
    const char* refused[] = {
        "/api/files?path=../secret.json",
        "/api/files?path=%2e%2e%2fsecret.json",
        "/api/files?path=%2E%2E/secret.json",
        "/api/files?path=examples/..%2f..%2fsecret.json",
        "/api/files?path=%252e%252e%252fsecret.json",
        "/api/files?path=/etc/passwd",
        "/api/files?path=%2Fetc%2Fpasswd",
        "/api/files?path=examples/leak.json",   // a symlink out of the root
        "/api/files?path=outside/secret.json",  // a directory symlink out of the root
        "/api/files?path=examples/notes.txt",   // not a served extension
        "/api/files?path=examples/none.json",
        "/api/files?path=examples%00.json",
        "/api/files",
    };
    for (const char* target : refused) {
        const int status = raw_get(target, &response);
        EXPECT_TRUE(status == 403 || status == 404 || (status == 400 && std::string(target) == "/api/files"))
            << target << " -> " << status;
        EXPECT_EQ(response.find("secret\": true"), std::string::npos) << target;
        EXPECT_NE(response.find("\"error\""), std::string::npos) << target;
    }
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioServer, StaticFilesComeOnlyFromTheAppFolder) {
    std::string response;
    EXPECT_EQ(raw_get("/", &response), 200);
    EXPECT_NE(response.find("studio app"), std::string::npos);
    for (const char* target : {"/../secret.json", "/%2e%2e/secret.json", "/%2E%2E%2Fsecret.json",
                               "/..%2fsecret.json", "/%252e%252e/secret.json", "/%252e%252e%252fsecret.json",
                               "/leak.html", "//etc/passwd", "/.%2e/secret.json", "/missing.js"}) {
        const int status = raw_get(target, &response);
        EXPECT_TRUE(status == 403 || status == 404) << target << " -> " << status;
        EXPECT_EQ(response.find("secret\": true"), std::string::npos) << target;
    }
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioServer, MalformedJsonIs400NamingTheProblem) {
    auto res = client()->Post("/api/sessions", "{\"canvas\": ", "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400);
    const Json error = Json::parse(res->body);
    EXPECT_NE(error.value("error", "").find("malformed JSON"), std::string::npos) << res->body;
    EXPECT_EQ(error.value("error", "").find('\n'), std::string::npos);
    int status = 0;
    EXPECT_NE(post("/api/sessions", Json::array({1}), &status).value("error", "").find("JSON object"),
              std::string::npos);
    EXPECT_EQ(status, 400);
    EXPECT_NE(post("/api/sessions", {{"options", Json::object()}}, &status).value("error", "").find("canvas"),
              std::string::npos);
    EXPECT_EQ(status, 400);
    EXPECT_NE(post("/api/sessions", {{"canvas", "blob:1"}}, &status).value("error", "").find("canvas"),
              std::string::npos);
    EXPECT_EQ(status, 400);
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioServer, UnknownAndBadOptionsAre400NamingThem) {
    int status = 0;
    Json error =
        post("/api/sessions", {{"canvas", "box:0,0,60,40"}, {"options", {{"nonsense", 1}}}}, &status);
    EXPECT_EQ(status, 400);
    EXPECT_NE(error.value("error", "").find("options.nonsense"), std::string::npos) << error.dump();
    error =
        post("/api/sessions", {{"canvas", "box:0,0,60,40"}, {"options", {{"iterations", "many"}}}}, &status);
    EXPECT_EQ(status, 400);
    EXPECT_NE(error.value("error", "").find("options.iterations"), std::string::npos) << error.dump();
    error = post("/api/sessions", {{"canvas", "box:0,0,60,40"}, {"options", {{"iterations", -3}}}}, &status);
    EXPECT_EQ(status, 400);
    EXPECT_NE(error.value("error", "").find("options.iterations"), std::string::npos) << error.dump();
    post("/api/sessions", {{"canvas", "box:0,0,60,40"}, {"options", {{"sigma", 1.5}, {"seed", 7}}}}, &status);
    EXPECT_EQ(status, 201);
}

TEST_F(StudioServer, UnknownRoutesAre404AndWrongMethods405) {
    int status = 0;
    EXPECT_TRUE(get("/api/nothing", &status).contains("error"));
    EXPECT_EQ(status, 404);
    get("/api/sessions/s999-0", &status);
    EXPECT_EQ(status, 404);
    get("/api/jobs/j999-0", &status);
    EXPECT_EQ(status, 404);
    auto res = client()->Put("/api/sessions", "{}", "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 405);
    EXPECT_EQ(res->get_header_value("Allow"), "GET, POST");
    res = client()->Post("/index.html", "{}", "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 405);
    res = client()->Delete("/api/palette");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 405);
}

TEST_F(StudioServer, RequestsOfOtherSitesAreRefused) {
    EXPECT_EQ(raw_status("GET /api/status HTTP/1.1\r\nHost: evil.example:8420\r\nConnection: close\r\n\r\n"),
              403);
    const std::string body = "{\"canvas\": \"box:0,0,10,10\"}";
    const auto post_from = [&](const std::string& origin) {
        return raw_status("POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nOrigin: " + origin +
                          "\r\nContent-Type: text/plain\r\nContent-Length: " + std::to_string(body.size()) +
                          "\r\nConnection: close\r\n\r\n" + body);
    };
    EXPECT_EQ(post_from("http://evil.example"), 403);
    EXPECT_EQ(post_from("http://127.0.0.1.evil.example"), 403);
    EXPECT_EQ(post_from("http://localhost:5173"), 201);  // a dev server of the front end
    EXPECT_TRUE(server_answers());
}

TEST_F(StudioServer, PaletteListsTheExamplesTesseraLoads) {
    int status = 0;
    const Json list = get("/api/palette", &status);
    EXPECT_EQ(status, 200);
    ASSERT_TRUE(list.contains("examples"));
    std::vector<std::string> names;
    for (const Json& e : list["examples"]) names.push_back(e.value("name", ""));
    EXPECT_EQ(names, (std::vector<std::string>{"sticks_2d", "two_class_2d"}));  // not leak.json (outside)
    EXPECT_EQ(list["examples"][0].value("path", ""), "examples/sticks_2d.json");
}

TEST_F(StudioServer, PaletteEntriesComeOnlyFromUnderTheRoot) {
    int status = 0;
    const std::string id = post("/api/sessions", {{"canvas", "box:0,0,60,40"}}, &status).value("id", "");
    ASSERT_EQ(status, 201);
    const std::string palette = "/api/sessions/" + id + "/palette";
    post(palette, {{"name", "x"}, {"path", "../secret.json"}}, &status);
    EXPECT_EQ(status, 403);
    post(palette, {{"name", "x"}, {"path", "examples/leak.json"}}, &status);
    EXPECT_EQ(status, 403);
    Json inline_exemplar = Json::parse(read("root/examples/sticks_2d.json"));
    inline_exemplar["types"][0]["mesh"] = "../secret.json";
    post(palette, {{"name", "x"}, {"exemplar", inline_exemplar}}, &status);
    EXPECT_EQ(status, 403);
    post(palette, {{"name", "x"}, {"path", "examples/sticks_2d.json"}, {"exemplar", inline_exemplar}},
         &status);
    EXPECT_EQ(status, 400);
    EXPECT_TRUE(server_answers());
}

}  // namespace

namespace {

// A browser offers "gzip, deflate, br"; the studio answers uncompressed all the same, because
// on 127.0.0.1 compression only costs time (Brotli at its best quality took ~200 ms of a paint
// stroke's answer). The app bundle and API answers are the big ones.
TEST_F(StudioServer, AnswersAreNotCompressedWhenABrowserOffersBrotli) {
    for (const char* target : {"/api/status", "/api/palette", "/api/files?path=examples/sticks_2d.json"}) {
        std::string response;
        const std::string request = std::string("GET ") + target +
                                    " HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept-Encoding: gzip, deflate, br\r\n"
                                    "Connection: close\r\n\r\n";
        EXPECT_EQ(raw_status(request, &response), 200) << target;
        const std::string head = response.substr(0, response.find("\r\n\r\n"));
        EXPECT_EQ(head.find("Content-Encoding"), std::string::npos) << target << "\n" << head;
    }
}

}  // namespace
