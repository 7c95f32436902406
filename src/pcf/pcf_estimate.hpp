// Mean PCFs and envelopes of individual PCFs for given class pairs (Eq. 2 and 3 with the
// conventions of tessera/pcf_synthesis.hpp): the computation analyze_distribution runs on
// the exemplar and measure_distribution on another arrangement.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "pcf/pcf_math.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

// Throws Error(option) naming the setting unless sigma, step and extent are finite and
// > 0 and the axis has a sane number of values (defined in analyze.cpp).
void check_analysis_settings(const PcfAnalysisSettings& settings);

// Elements as the PCF method sees them: centre, radius and model class (-1: a type the
// model does not know, ignored).
struct PcfPoints {
    std::vector<Vec3> p;
    std::vector<double> radius;
    std::vector<int> cls;
};

// The elements of `data` with `class_of_type[t]` as the class of type t. Throws
// Error(input) mentioning `what` for data that is not 2D, multi-sample elements,
// non-finite positions or radii < 0 (naming the element's type).
PcfPoints pcf_points(const Exemplar& data, const std::vector<int>& class_of_type, const std::string& what);

// One PcfEnvelope per (parent, child) of `pairs` (their mean, lower, upper are filled):
// the reference elements are the child's, the neighbours the parent's. Individual PCFs
// divide by the possible neighbours n_parent (n_child - 1 within a class), so the mean is
// the average of the individual PCFs and lies inside the envelope. A child class without
// elements gives zeros. `area` is |W| of `domain`. The result does not depend on the
// number of threads (fixed blocks, reduced in order; 0 = all).
std::vector<PcfEnvelope> estimate_pcfs(const PcfPoints& points, int classes, const Domain& domain, double area,
                                       double r_max, const Axis& axis, const std::vector<PcfEnvelope>& pairs,
                                       int threads);

// The closest approach on the normalised axis (pair_distance.hpp) between the elements of
// each class pair of `pairs` (two different classes), at most `cap`: cap when no pair of
// these classes comes closer. Exact (every pair within the distance that reaches cap).
std::vector<double> closest_approaches(const PcfPoints& points, const Domain& domain, double r_max,
                                       const std::vector<std::pair<int, int>>& pairs, int classes, double cap);

}  // namespace tessera::pcf
