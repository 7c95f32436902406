// apps/tessera/suggest.cpp — closest subcommand or option name (suggest.hpp).
#include "suggest.hpp"

#include <algorithm>

namespace tessera_cli {
namespace {

std::string without_dashes(const std::string& s) {
    const size_t start = s.find_first_not_of('-');
    return start == std::string::npos ? "" : s.substr(start);
}

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

int edit_distance(const std::string& a, const std::string& b) {
    // Optimal string alignment distance, three rows of the dynamic programme.
    const size_t n = a.size(), m = b.size();
    std::vector<int> before(m + 1), previous(m + 1), current(m + 1);
    for (size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
    for (size_t i = 1; i <= n; ++i) {
        current[0] = static_cast<int>(i);
        for (size_t j = 1; j <= m; ++j) {
            const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[m];
}

std::optional<std::string> closest_match(const std::string& typed, const std::vector<std::string>& candidates) {
    const std::string word = without_dashes(typed);
    if (word.size() < 2) return std::nullopt;  // one letter is close to every short option
    const int allowed = 1 + static_cast<int>(word.size()) / 4;
    std::optional<std::string> best;
    int best_score = allowed + 1;
    for (const std::string& candidate : candidates) {
        const std::string name = without_dashes(candidate);
        int score = edit_distance(word, name);
        const bool prefix = std::min(word.size(), name.size()) >= 3 &&
                            (starts_with(word, name) || starts_with(name, word));
        if (prefix) score = std::min(score, 1);
        if (score < best_score) best = candidate, best_score = score;
    }
    return best;
}

}  // namespace tessera_cli
