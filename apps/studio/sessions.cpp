// apps/studio/sessions.cpp — the session registry (sessions.hpp).
#include "apps/studio/sessions.hpp"

#include <cstdio>

namespace tessera_studio {

IdMaker::IdMaker(char prefix) : prefix_(prefix), random_(std::random_device{}()) {}

std::string IdMaker::next() {
    std::lock_guard lock(mutex_);
    char text[48];
    std::snprintf(text, sizeof text, "%c%llu-%08llx", prefix_, static_cast<unsigned long long>(++counter_),
                  static_cast<unsigned long long>(random_() & 0xffffffffULL));
    return text;
}

Session::Session(std::string id_, std::string canvas_text_, int dimension_, tessera::BrushCanvas canvas_)
    : id(std::move(id_)),
      canvas_text(std::move(canvas_text_)),
      dimension(dimension_),
      canvas(std::move(canvas_)) {}

void check_idle(const Session& session) {
    if (!session.job.empty())
        throw ApiError(409,
                       "session " + session.id + " is busy with job " + session.job + "; wait or cancel it");
}

SessionRegistry::SessionRegistry(size_t max_sessions) : max_sessions_(max_sessions) {}

void SessionRegistry::add(std::shared_ptr<Session> session) {
    std::lock_guard lock(mutex_);
    if (sessions_.size() >= max_sessions_)
        throw ApiError(503,
                       "too many sessions open (" + std::to_string(max_sessions_) + "); delete one first");
    sessions_[session->id] = std::move(session);
}

std::shared_ptr<Session> SessionRegistry::find(const std::string& id) const {
    std::lock_guard lock(mutex_);
    const auto it = sessions_.find(id);
    return it == sessions_.end() ? nullptr : it->second;
}

std::shared_ptr<Session> SessionRegistry::remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    const auto it = sessions_.find(id);
    if (it == sessions_.end()) return nullptr;
    auto session = std::move(it->second);
    sessions_.erase(it);
    return session;
}

std::vector<std::string> SessionRegistry::ids() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> ids;
    for (const auto& [id, session] : sessions_) ids.push_back(id);
    return ids;
}

std::shared_ptr<Session> find_session(const SessionRegistry& registry, const std::string& id) {
    auto session = registry.find(id);
    if (!session) throw ApiError(404, "no session '" + id + "'");
    return session;
}

}  // namespace tessera_studio
