// apps/studio/server_context.hpp — what the route handlers of one server share (private to
// apps/studio): its configuration, sessions, jobs and example list, each with its own lock.
#pragma once

#include <atomic>
#include <cstdint>

#include "apps/studio/jobs.hpp"
#include "apps/studio/palette.hpp"
#include "apps/studio/router.hpp"
#include "apps/studio/server.hpp"
#include "apps/studio/session_ops.hpp"
#include "apps/studio/sessions.hpp"

namespace tessera_studio {

struct ServerContext {
    explicit ServerContext(StudioConfig config);

    const StudioConfig config;  // root and app_dir canonical
    SessionRegistry sessions;
    JobRunner jobs;
    ExampleCatalog examples;
    IdMaker job_ids{'j'};
    std::atomic<bool> stopping{false};
    std::atomic<int> port{0};
    // Event streams hold a worker thread each: at most max_streams at once, so that they
    // never take every worker.
    std::atomic<int> streams{0};
    const int max_streams;
    std::atomic<std::uint64_t> exports{0};
};

// Starts a job applying `ops` to `session` (one undo step, `step`); returns its id. 409 when
// the session is busy, 503 when the server runs its maximum of jobs.
std::string start_ops_job(ServerContext& ctx, const std::shared_ptr<Session>& session,
                          std::vector<OpRequest> ops, StepOf step = {});

// The routes, by group: static files, /api/files and /api/palette; sessions; jobs.
void add_file_routes(Router& router, ServerContext& ctx);
void add_session_routes(Router& router, ServerContext& ctx);
void add_job_routes(Router& router, ServerContext& ctx);

}  // namespace tessera_studio
