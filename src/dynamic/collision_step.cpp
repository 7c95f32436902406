#include "dynamic/collision_step.hpp"

#include "dynamic/element_contacts.hpp"

namespace tessera::dynamic {

// Every particle is an element of its own, so the closest approach between elements is the
// closest approach between samples.
double exemplar_collision_radius(const Animation& exemplar, double quantile) {
    return 0.5 * exemplar_contact_distance(exemplar, quantile);
}

CollisionStep::CollisionStep(const Animation& exemplar, const Domain& domain, bool periodic)
    : domain_(domain),
      dimension_(exemplar.structure.dimension),
      radius_(exemplar_collision_radius(exemplar, closest_quantile)) {
    options_.no_gravity = true;  // collisions only: the motion is the synthesis's
    options_.friction = 0.0;     // bodies at rest: friction would only hold overlaps
    options_.damping = 1.0;      // and no velocity survives a step
    options_.periodic = periodic;
    // Each step removes a whole overlap, and pushing one pair apart can press it into a
    // third particle: 20 steps settle a crowded cluster (5 left half of them).
    options_.substeps = 20;
    options_.overlap_correction = 1.0;
    scratch_.dimension = dimension_;
    scratch_.types.emplace_back().name = "particle";
}

void CollisionStep::add_particle(const Vec3& p, bool image) {
    const int index = static_cast<int>(scratch_.elements.size());
    Sample& s = scratch_.samples.emplace_back();
    s.p = p;
    s.element = index;
    Element& e = scratch_.elements.emplace_back();
    e.first_sample = index;
    e.position = p;
    e.radius = radius_;
    e.locked = image;  // an image is a wall: its particle is moved by its own body
}

// With wrap, a pair across the seam is seen once: the image of one particle one period
// away, as a fixed body next to the other, which moves the whole overlap (a pair inside
// shares it; either way the pair ends a collision distance apart). Of the turns t and -t
// only the one whose first non-zero component is positive makes images, so no pair is
// pushed twice.
void CollisionStep::add_images(const std::vector<Vec3>& positions) {
    const Box& box = domain_.bounds();
    const Vec3 period = box.size();
    const double reach = 2.0 * radius_;
    std::vector<Vec3> turns;
    for (int code = 0; code < 27; ++code) {
        const Vec3 t{double(code % 3 - 1), double(code / 3 % 3 - 1), double(code / 9 - 1)};
        if (dimension_ == 2 && t.z != 0.0) continue;
        const double first = t.x != 0.0 ? t.x : (t.y != 0.0 ? t.y : t.z);
        if (first > 0.0) turns.push_back(t);
    }
    for (const Vec3& p : positions)
        for (const Vec3& t : turns) {
            Vec3 image = p;
            bool near = true;
            for (int k = 0; k < dimension_ && near; ++k) {
                image[k] += t[k] * period[k];
                near = image[k] > box.lo[k] - reach && image[k] < box.hi[k] + reach;
            }
            if (near) add_particle(image, true);
        }
}

int CollisionStep::apply(std::vector<Vec3>& positions) {
    if (!(radius_ > 0.0) || positions.empty()) return 0;
    scratch_.samples.clear();
    scratch_.elements.clear();
    for (const Vec3& p : positions) add_particle(p, false);
    if (options_.periodic) add_images(positions);
    step_physics(scratch_, domain_, options_);
    int moved = 0;
    for (size_t i = 0; i < positions.size(); ++i) {
        if (scratch_.samples[i].p != positions[i]) ++moved;
        positions[i] = scratch_.samples[i].p;
    }
    return moved;
}

}  // namespace tessera::dynamic
