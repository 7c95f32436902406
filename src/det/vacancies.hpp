// Filling holes: where patches meet, their elements may not line up and leave gaps; a
// seam duplicate that is not copied leaves a vacancy in a lattice; and during the
// iterations the least-squares assignment can open a hole that nothing fills again (the
// paper has no step that adds elements; section 4.1 mentions incremental add as an
// alternative initialization). fill_vacancies puts copies of exemplar elements into the
// emptiest places of the domain: every empty ball (rim to rim, inside the domain) larger
// than `hole_radius`, and, with `reach_count`, the largest holes until every type has its
// count (the exemplar's density where its elements are times the domain's measure).
// Candidates are a lattice of a quarter spacing (a third in 3D) ranked by their clearance
// in a lazily updated heap. The inserted type is the one furthest below its count among
// those whose closest exemplar distances (hard core) to the elements around the hole
// hold; the element copied is a keyed random one of that type, turned by the field.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/crowding_repair.hpp"
#include "det/model.hpp"
#include "det/provenance.hpp"

namespace tessera::det {

struct VacancySettings {
    double hole_radius = 0.0;  // fill empty balls larger than this; 0 = none
    // ... but take a type past (1 + count_allowance) times its count only for a hole larger
    // than must_fill_radius (a count is an estimate; a hole that large is a defect anyway).
    double count_allowance = INFINITY;
    double must_fill_radius = 0.0;
    bool reach_count = false;  // also fill the largest holes until the counts are reached
    std::uint64_t seed = 1;
    std::uint64_t round = 0;   // which call (keys the random choices)
};

struct VacancyReport {
    int added = 0;
    bool bound_hit = false;  // stopped by the insertion bound with holes left
};

VacancyReport fill_vacancies(Provenance into, const Exemplar& exemplar, const Domain& domain, const Params& params,
                             const core::CrowdingBounds& tails, const VacancySettings& settings);

// The candidate centres of holes: a lattice of a quarter spacing (a third in 3D) inside the domain.
std::vector<Vec3> vacancy_candidates(const Domain& domain, int dimension, double spacing);

// The largest empty ball of the exemplar in its own window (rim to rim): the size of hole
// the exemplar itself shows, against which output holes are judged. A layered exemplar
// (thinner than 2 x radius along one axis) is measured in the plane of its layer.
double exemplar_hole_radius(const Exemplar& exemplar, double spacing, double radius);

}  // namespace tessera::det
