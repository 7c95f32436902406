// `tessera studio` end to end: the address on the first line of stdout, the server
// answering there, a graceful stop on SIGTERM and on SIGINT during a long job (exit 0,
// within a bound), and its option errors as one line with their exit codes.
#include <fcntl.h>
#include <httplib.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli/cli_fixture.hpp"

extern char** environ;

namespace {

using tessera_cli_test::CliFixture;
using tessera_cli_test::Result;
using Json = nlohmann::json;

class StudioCli : public CliFixture {
protected:
    // Starts `tessera studio --port 0 -q --root ROOT` with stdout to a file; its pid.
    pid_t start_studio() {
        posix_spawn_file_actions_t files;
        posix_spawn_file_actions_init(&files);
        posix_spawn_file_actions_addopen(&files, 1, path("studio.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
        const std::string cli = TESSERA_CLI, root = TESSERA_SOURCE_DIR;
        const char* argv[] = {cli.c_str(), "studio", "--port", "0", "-q", "--root", root.c_str(), nullptr};
        pid_t pid = 0;
        const int error =
            posix_spawn(&pid, cli.c_str(), &files, nullptr, const_cast<char* const*>(argv), environ);
        posix_spawn_file_actions_destroy(&files);
        EXPECT_EQ(error, 0);
        return error == 0 ? pid : -1;
    }
    // The port from the first line of stdout, waiting at most 10 s for it; 0 if none came.
    int port_of_studio() const {
        const std::string prefix = "tessera studio: http://127.0.0.1:";
        for (int k = 0; k < 500; ++k) {
            const std::string out = tessera_cli_test::read_text(path("studio.out"));
            if (out.find('\n') != std::string::npos)
                return out.rfind(prefix, 0) == 0 ? std::stoi(out.substr(prefix.size())) : 0;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return 0;
    }
    // The exit code after `signal`, waiting at most 10 s (then killed: -1).
    static int stop_with(pid_t pid, int signal) {
        ::kill(pid, signal);
        for (int k = 0; k < 1000; ++k) {
            int status = 0;
            if (::waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        return -1;
    }
};

TEST_F(StudioCli, ServesOnThePrintedPortAndStopsOnSigterm) {
    const pid_t pid = start_studio();
    ASSERT_GT(pid, 0);
    const int port = port_of_studio();
    ASSERT_GT(port, 0) << tessera_cli_test::read_text(path("studio.out"));
    httplib::Client client("127.0.0.1", port);
    const auto res = client.Get("/api/status");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    EXPECT_EQ(stop_with(pid, SIGTERM), 0);
}

TEST_F(StudioCli, SigintDuringAJobCancelsItAndExitsCleanly) {
    const pid_t pid = start_studio();
    ASSERT_GT(pid, 0);
    const int port = port_of_studio();
    ASSERT_GT(port, 0);
    httplib::Client client("127.0.0.1", port);
    const auto made = client.Post("/api/sessions", R"({"canvas": "box:0,0,400,400"})", "application/json");
    ASSERT_TRUE(made);
    const std::string id = Json::parse(made->body).value("id", "");
    client.Post(("/api/sessions/" + id + "/palette").c_str(),
                R"({"name": "s", "path": "examples/sticks_2d.json"})", "application/json");
    const auto started =
        client.Post(("/api/sessions/" + id + "/ops").c_str(), R"({"op": "fill"})", "application/json");
    ASSERT_TRUE(started);
    EXPECT_EQ(started->status, 202) << started->body;
    const auto begin = std::chrono::steady_clock::now();
    EXPECT_EQ(stop_with(pid, SIGINT), 0);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), 5.0);
}

TEST_F(StudioCli, BadOptionsAndFoldersAreOneLineErrors) {
    Result r = run("studio --port 70000");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--port"), std::string::npos) << r.err;
    r = run("studio --port 0 --root '" + path("nowhere") + "'");
    EXPECT_EQ(r.code, 5);
    EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    r = run("studio --port 0 --max-body 0");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--max-body"), std::string::npos) << r.err;
}

}  // namespace
