// apps/studio/routes_jobs.cpp — jobs: their state, their progress as server-sent events,
// and cancelling them.
#include <httplib.h>

#include <limits>

#include "apps/studio/server_context.hpp"

namespace tessera_studio {
namespace {

// How long an event stream waits for news before it sends a keep-alive comment (which is
// also how it notices a client that went away, and a server that stops).
constexpr std::chrono::milliseconds stream_tick{250};

std::shared_ptr<Job> find_job(const ServerContext& ctx, const std::string& id) {
    auto job = ctx.jobs.find(id);
    if (!job) throw ApiError(404, "no job '" + id + "'");
    return job;
}

// Holds one of the server's event-stream places while a stream lives.
struct StreamSlot {
    explicit StreamSlot(ServerContext& c) : ctx(c) {
        if (++ctx.streams > ctx.max_streams) {
            --ctx.streams;
            throw ApiError(503, "too many event streams open (" + std::to_string(ctx.max_streams) +
                                    "); poll GET /api/jobs/ID");
        }
    }
    ~StreamSlot() { --ctx.streams; }
    StreamSlot(const StreamSlot&) = delete;
    StreamSlot& operator=(const StreamSlot&) = delete;
    ServerContext& ctx;
};

void stream_events(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    auto job = find_job(ctx, r.params[0]);
    auto slot = std::make_shared<StreamSlot>(ctx);
    res.set_header("Cache-Control", "no-cache");
    auto seen = std::make_shared<std::uint64_t>(std::numeric_limits<std::uint64_t>::max());
    res.set_chunked_content_provider(
        "text/event-stream", [&ctx, job, slot, seen](size_t, httplib::DataSink& sink) {
            const JobSnapshot s = job->wait_for_change(*seen, stream_tick);
            std::string text = ": keep-alive\n\n";
            if (s.version != *seen) {
                *seen = s.version;
                text = "event: job\ndata: " + job_json(job->id(), job->session(), s).dump() + "\n\n";
            }
            if (!sink.write(text.data(), text.size())) return false;  // the client went away
            if (s.state != JobState::running || ctx.stopping.load()) sink.done();
            return true;
        });
}

}  // namespace

void add_job_routes(Router& router, ServerContext& ctx) {
    const std::string one = "/api/jobs/{}";
    router.add("GET", one, [&ctx](const RouteRequest& r, httplib::Response& res) {
        const auto job = find_job(ctx, r.params[0]);
        send_json(res, 200, job_json(job->id(), job->session(), job->snapshot()));
    });
    router.add("GET", one + "/events",
               [&ctx](const RouteRequest& r, httplib::Response& res) { stream_events(ctx, r, res); });
    router.add("DELETE", one, [&ctx](const RouteRequest& r, httplib::Response& res) {
        const auto job = find_job(ctx, r.params[0]);
        job->cancel();
        // 202: the cancel lands at the library's next progress call (within about 0.1 s).
        send_json(res, 202, job_json(job->id(), job->session(), job->snapshot()));
    });
}

}  // namespace tessera_studio
