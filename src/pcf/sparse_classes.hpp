// Classes with too few elements for PCFs (PcfSparseClass, pcf_synthesis.hpp): what the
// analysis records of them, and the checks synthesis places them by. Private to the library.
#pragma once

#include <vector>

#include "pcf/pcf_estimate.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

// Whether class c of `model` is placed by the sparse fallback; the entry or nullptr.
const PcfSparseClass* sparse_class(const PcfModel& model, int c);

// The fallback's parameters of every class with fewer than kPcfSparseCount elements (at
// least 1), from the exemplar's points: brute force over its few elements.
std::vector<PcfSparseClass> analyse_sparse_classes(const PcfPoints& points, const PcfModel& model);

}  // namespace tessera::pcf
