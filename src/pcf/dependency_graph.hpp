// The dependency graph of the PCF method (section 3.2): which classes each class
// depends on, checked to be a DAG, and the order in which synthesis processes them.
#pragma once

#include <string>
#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera::pcf {

// parents[c] for the exemplar's types: ElementType::depends_on resolved by name (in the
// order listed), or every earlier type when it is unset. Throws Error(input) naming the
// class for an unknown or repeated name, and for a cycle (naming the classes on it).
std::vector<std::vector<int>> dependency_parents(const std::vector<ElementType>& types);

// A topological order of the DAG given by parents (every class after its parents), by
// Kahn's algorithm taking the lowest ready index first, so it is stable: without
// dependencies, or with the default graph, it is 0, 1, 2, ... Throws Error(input) naming
// the classes of a cycle (`names` gives the class names for the message).
std::vector<int> topological_order(const std::vector<std::vector<int>>& parents,
                                   const std::vector<std::string>& names);

}  // namespace tessera::pcf
