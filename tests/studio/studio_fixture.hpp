// A studio server started in-process on 127.0.0.1 and an ephemeral port, over a project
// root of its own in a temporary directory (two examples, a file outside the root and
// symlinks pointing at it), with an httplib client and a raw-socket request helper for
// requests whose bytes must reach the server exactly as written.
#pragma once

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "apps/studio/server.hpp"
#include "temp_dir.hpp"

namespace tessera::test {

class StudioFixture : public TempDirTest {
protected:
    using Json = nlohmann::json;
    static constexpr size_t max_body = 256 * 1024;  // small, so the oversized body is quick to send

    void SetUp() override {
        TempDirTest::SetUp();
        namespace fs = std::filesystem;
        root_ = dir_ / "root";
        app_ = dir_ / "app";
        fs::create_directories(root_ / "examples");
        fs::create_directories(app_);
        for (const char* name : {"sticks_2d.json", "two_class_2d.json"})
            fs::copy_file(std::string(TESSERA_SOURCE_DIR) + "/examples/" + name, root_ / "examples" / name);
        write("root/examples/notes.txt", "not served");
        write("secret.json", "{\"secret\": true}");
        write("app/index.html", "<html>studio app</html>");
        fs::create_symlink(dir_ / "secret.json", root_ / "examples" / "leak.json");
        fs::create_symlink(dir_ / "secret.json", app_ / "leak.html");
        fs::create_directory_symlink(dir_, root_ / "outside");
        tessera_studio::StudioConfig config;
        config.host = "127.0.0.1";
        config.port = 0;
        config.root = root_;
        config.app_dir = app_;
        config.max_body = max_body;
        configure(config);
        server_ = std::make_unique<tessera_studio::StudioServer>(config);
        server_->start();
        port_ = server_->port();
    }
    void TearDown() override {
        if (server_) server_->stop();
        server_.reset();
        TempDirTest::TearDown();
    }
    // Lets a test change the configuration before the server starts.
    virtual void configure(tessera_studio::StudioConfig&) {}

    std::unique_ptr<httplib::Client> client() const {
        auto c = std::make_unique<httplib::Client>("127.0.0.1", port_);
        c->set_connection_timeout(5, 0);
        c->set_read_timeout(60, 0);
        c->set_write_timeout(10, 0);
        return c;
    }

    // The status of `request` sent as written (it must end with an empty line); 0 when no
    // answer came within 10 s.
    int raw_status(const std::string& request, std::string* response = nullptr) const {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        if (fd < 0) return 0;
        timeval timeout{10, 0};
        ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(static_cast<uint16_t>(port_));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        std::string received;
        if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
            size_t sent = 0;
            while (sent < request.size()) {
                const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
                if (n <= 0) break;
                sent += static_cast<size_t>(n);
            }
            char buffer[4096];
            for (int reads = 0; reads < 10000; ++reads) {
                const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
                if (n <= 0) break;
                received.append(buffer, static_cast<size_t>(n));
            }
        }
        ::close(fd);
        if (response) *response = received;
        if (received.rfind("HTTP/1.1 ", 0) != 0 || received.size() < 12) return 0;
        return std::stoi(received.substr(9, 3));
    }
    // A GET of `target` as written, on a connection closed after it.
    int raw_get(const std::string& target, std::string* response = nullptr) const {
        return raw_status("GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n",
                          response);
    }

    bool server_answers() const {
        auto res = client()->Get("/api/status");
        return res && res->status == 200;
    }

    // POST of a JSON body; the parsed answer (null when it is not JSON) and its status.
    Json post(const std::string& path, const Json& body, int* status = nullptr) const {
        auto res = client()->Post(path.c_str(), body.dump(), "application/json");
        return answer(res, status);
    }
    Json get(const std::string& path, int* status = nullptr) const {
        return answer(client()->Get(path.c_str()), status);
    }
    Json del(const std::string& path, int* status = nullptr) const {
        return answer(client()->Delete(path.c_str()), status);
    }

    static Json answer(const httplib::Result& res, int* status) {
        if (status) *status = res ? res->status : 0;
        if (!res) return Json();
        return Json::parse(res->body, nullptr, false);
    }

    // A session over `canvas` with the sticks exemplar as palette entry "sticks".
    std::string sticks_session(const std::string& canvas, const Json& options = Json::object()) const {
        int status = 0;
        const Json made = post("/api/sessions", {{"canvas", canvas}, {"options", options}}, &status);
        EXPECT_EQ(status, 201) << made.dump();
        const std::string id = made.value("id", "");
        post("/api/sessions/" + id + "/palette", {{"name", "sticks"}, {"path", "examples/sticks_2d.json"}},
             &status);
        EXPECT_EQ(status, 201);
        return id;
    }

    // The job's last state, polled every 20 ms for at most `seconds`.
    Json wait_for_job(const std::string& job, double seconds = 120) const {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        Json state;
        while (std::chrono::steady_clock::now() < deadline) {
            state = get("/api/jobs/" + job);
            if (state.value("state", "") != "running") return state;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return state;
    }

    std::filesystem::path root_, app_;
    std::unique_ptr<tessera_studio::StudioServer> server_;
    int port_ = 0;
};

}  // namespace tessera::test
