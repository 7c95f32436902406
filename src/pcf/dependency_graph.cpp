// Dependency DAG of the PCF method (section 3.2, Figure 3): parents from
// ElementType::depends_on, Kahn's topological sort, and cycle reporting. Synthesis
// processes classes in this order, each one against its parents' elements.
#include "pcf/dependency_graph.hpp"

#include <algorithm>

#include "tessera/error.hpp"

namespace tessera::pcf {
namespace {

std::string quoted(const std::string& name) { return "'" + name + "'"; }

// A cycle among `remaining` classes (each still has a remaining parent, or Kahn's
// algorithm would have taken it): follow parent links from the lowest one until a class
// repeats; the loop found is a cycle. Returned in dependency direction: each class
// depends on the next, and the last on the first.
std::vector<int> find_cycle(const std::vector<std::vector<int>>& parents, const std::vector<bool>& remaining) {
    const int n = static_cast<int>(parents.size());
    int start = 0;
    while (start < n && !remaining[start]) ++start;
    std::vector<int> seen_at(n, -1), path;
    int c = start;
    while (seen_at[c] < 0) {
        seen_at[c] = static_cast<int>(path.size());
        path.push_back(c);
        int next = -1;
        for (int p : parents[c])
            if (remaining[p] && (next < 0 || p < next)) next = p;
        c = next;  // never -1: a remaining class keeps a remaining parent
    }
    return std::vector<int>(path.begin() + seen_at[c], path.end());
}

}  // namespace

std::vector<std::vector<int>> dependency_parents(const std::vector<ElementType>& types) {
    const int n = static_cast<int>(types.size());
    std::vector<std::vector<int>> parents(n);
    std::vector<std::string> names;
    for (const auto& t : types) names.push_back(t.name);
    for (int c = 0; c < n; ++c) {
        if (!types[c].depends_on) {
            for (int p = 0; p < c; ++p) parents[c].push_back(p);  // the default: every earlier class
            continue;
        }
        for (const std::string& name : *types[c].depends_on) {
            const auto it = std::find(names.begin(), names.end(), name);
            if (it == names.end())
                throw Error(ErrorKind::input, "class " + quoted(names[c]) + " depends on unknown class " + quoted(name));
            const int p = static_cast<int>(it - names.begin());
            if (std::find(parents[c].begin(), parents[c].end(), p) != parents[c].end())
                throw Error(ErrorKind::input, "class " + quoted(names[c]) + " lists " + quoted(name) +
                                                  " twice in depends_on");
            parents[c].push_back(p);
        }
    }
    topological_order(parents, names);  // throws on a cycle
    return parents;
}

std::vector<int> topological_order(const std::vector<std::vector<int>>& parents,
                                   const std::vector<std::string>& names) {
    const int n = static_cast<int>(parents.size());
    std::vector<int> missing(n);  // parents not yet placed
    std::vector<std::vector<int>> children(n);
    for (int c = 0; c < n; ++c) {
        missing[c] = static_cast<int>(parents[c].size());
        for (int p : parents[c]) children[p].push_back(c);
    }
    std::vector<int> order;
    std::vector<bool> placed(n, false);
    // n is the number of classes (a handful): a linear scan for the lowest ready index
    // keeps the order obviously stable.
    for (int step = 0; step < n; ++step) {
        int next = -1;
        for (int c = 0; c < n && next < 0; ++c)
            if (!placed[c] && missing[c] == 0) next = c;
        if (next < 0) break;
        placed[next] = true;
        order.push_back(next);
        for (int child : children[next]) --missing[child];
    }
    if (static_cast<int>(order.size()) == n) return order;

    std::vector<bool> remaining(n);
    for (int c = 0; c < n; ++c) remaining[c] = !placed[c];
    const std::vector<int> cycle = find_cycle(parents, remaining);
    std::string text;
    for (int c : cycle) text += quoted(names[c]) + " -> ";
    text += quoted(names[cycle.front()]);
    throw Error(ErrorKind::input, "the class dependencies form a cycle: " + text + " (each depends on the next)");
}

}  // namespace tessera::pcf
