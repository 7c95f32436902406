// DetSession (include/tessera/det_session.hpp): the neighbourhood method as an object that
// keeps its state. Locked elements leave every call bit-identical; a region's iterations
// move only what the region holds; a second region initialized next to a finished one
// joins it without crowding the seam; existing arrangements are checked against the
// exemplar's types.
#include <gtest/gtest.h>

#include <map>

#include "core/parallel.hpp"
#include "quality_data.hpp"
#include "tessera/det_session.hpp"
#include "tessera/error.hpp"

using namespace tessera;

namespace {

// Every element of `before` for which `pick` holds, by id, equal to the bit in `after`.
template <class Pick>
int expect_unchanged(const Arrangement& before, const Arrangement& after, Pick pick, const std::string& what) {
    std::map<std::uint64_t, int> by_id;
    for (size_t e = 0; e < after.elements.size(); ++e) by_id[after.elements[e].id] = static_cast<int>(e);
    int checked = 0;
    for (const Element& a : before.elements) {
        if (!pick(a)) continue;
        ++checked;
        const auto it = by_id.find(a.id);
        if (it == by_id.end()) {
            ADD_FAILURE() << what << ": element " << a.id << " is gone";
            continue;
        }
        const Element& b = after.elements[it->second];
        EXPECT_EQ(a.type, b.type) << what << " element " << a.id;
        EXPECT_EQ(a.locked, b.locked) << what << " element " << a.id;
        EXPECT_TRUE(a.position.x == b.position.x && a.position.y == b.position.y && a.position.z == b.position.z)
            << what << " element " << a.id << " moved";
        EXPECT_TRUE(a.orientation.w == b.orientation.w && a.orientation.z == b.orientation.z) << what << " element " << a.id;
        EXPECT_EQ(a.sample_count, b.sample_count) << what << " element " << a.id;
        if (a.sample_count != b.sample_count) continue;
        for (int s = 0; s < a.sample_count; ++s) {
            const Vec3& p = before.samples[a.first_sample + s].p;
            const Vec3& q = after.samples[b.first_sample + s].p;
            EXPECT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z) << what << " element " << a.id << " sample " << s;
        }
    }
    return checked;
}

Arrangement locked_left_half(const Exemplar& ex, double& middle) {
    Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0));
    middle = out.domain.bounds().center().x;
    for (Element& e : out.elements) e.locked = e.position.x < middle;
    return out;
}

}  // namespace

TEST(DetSession, LockedElementsAreBitIdenticalAfterIterationsAndTheFinalPasses) {
    for (const char* name : {"poisson_disk_2d", "two_class_2d", "rods_3d"}) {
        const Exemplar ex = test::example(name);
        double middle = 0.0;
        const Arrangement start = locked_left_half(ex, middle);
        DetSession session(ex);
        session.set_arrangement(start);
        session.iterate(4);
        session.finish();
        const int locked = expect_unchanged(start, session.arrangement(), [](const Element& e) { return e.locked; }, name);
        EXPECT_GT(locked, 10) << name;
    }
}

TEST(DetSession, ARegionsIterationsMoveOnlyTheElementsInIt) {
    const Exemplar ex = test::example("two_class_2d");
    const Arrangement start = synthesize_det(ex, ex.domain.scaled(2.0));
    const Box b = start.domain.bounds();
    const Domain left = Domain::box(b.lo, {b.center().x, b.hi.y, 0}, 2);
    DetSession session(ex);
    session.set_arrangement(start);
    session.iterate(left, 3);
    const auto outside = [&](const Element& e) { return !left.inside(e.position); };
    EXPECT_GT(expect_unchanged(start, session.arrangement(), outside, "outside the region"), 10);
    // ... and the elements inside did move.
    double moved = 0.0;
    std::map<std::uint64_t, Vec3> where;
    for (const Element& e : session.arrangement().elements) where[e.id] = e.position;
    for (const Element& e : start.elements)
        if (left.inside(e.position) && where.count(e.id)) moved = std::max(moved, norm(where[e.id] - e.position));
    EXPECT_GT(moved, 1e-6);
}

TEST(DetSession, ASecondRegionJoinsTheFirstWithoutCrowdingTheSeam) {
    const Exemplar ex = test::example("poisson_disk_2d");
    const Box in = ex.domain.bounds();
    const Vec3 size = in.size();
    const Domain first = Domain::box(in.lo, in.lo + Vec3{2 * size.x, 2 * size.y, 0}, 2);
    const Domain second = Domain::box(in.lo + Vec3{2 * size.x, 0, 0}, in.lo + Vec3{4 * size.x, 2 * size.y, 0}, 2);
    const Domain both = Domain::box(in.lo, in.lo + Vec3{4 * size.x, 2 * size.y, 0}, 2);
    DetSession session(ex);
    session.initialize(first);
    session.iterate(5);
    const Arrangement after_first = session.arrangement();
    session.set_domain(both);
    const int added = session.initialize(second);
    session.iterate(second, 5);
    // The first region's elements away from the seam band are untouched.
    EXPECT_GT(expect_unchanged(after_first, session.arrangement(),
                               [&](const Element& e) { return !second.inside(e.position); }, "first region"),
              100);
    const Arrangement& out = session.arrangement();
    EXPECT_NEAR(static_cast<double>(added), static_cast<double>(after_first.elements.size()),
                0.1 * after_first.elements.size());
    for (const CrowdingPair& c : crowding(ex, out))
        EXPECT_LE(c.output_share, 1.5 * c.exemplar_share + 1.0 / std::max<long>(1, c.output_elements))
            << c.name_a << ">" << c.name_b;
    // No element of the second region on top of one of the first, across the seam.
    const double spacing = mean_nearest_neighbor_distance(ex);
    const NearestNeighborStats nn = nearest_neighbor_distances(out);
    EXPECT_GT(nn.min, 0.3 * spacing);
}

TEST(DetSession, AnExistingArrangementMustUseTheExemplarsTypes) {
    const Exemplar ex = test::example("two_class_2d");
    Arrangement other = synthesize_det(ex, ex.domain);
    other.types[1].name = "pebble-not-in-the-exemplar";
    DetSession session(ex);
    try {
        session.set_arrangement(other);
        FAIL() << "an unknown type was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("pebble-not-in-the-exemplar"), std::string::npos) << e.what();
    }
}

TEST(DetSession, SynthesizeDetIsInitializeIterateFinish) {
    const Exemplar ex = test::example("two_class_2d");
    DetOptions o;
    o.iterations = 3;
    const Arrangement one_shot = synthesize_det(ex, ex.domain.scaled(2.0), o);
    DetSession session(ex, o);
    session.initialize(ex.domain.scaled(2.0));
    session.iterate(o.iterations);
    session.finish();
    const Arrangement& held = session.arrangement();
    ASSERT_EQ(one_shot.samples.size(), held.samples.size());
    for (size_t i = 0; i < held.samples.size(); ++i) {
        EXPECT_EQ(one_shot.samples[i].p.x, held.samples[i].p.x);
        EXPECT_EQ(one_shot.samples[i].p.y, held.samples[i].p.y);
    }
}

TEST(DetSession, EveryParallelLoopKeepsToTheThreadsOption) {
    // A polygon domain reaches the translated-overlap table of the pair relaxation; the
    // two-class field data reach the structure range's pair correlation.
    const Exemplar ex = test::field_pattern("amacrine");
    const Box b = ex.domain.bounds();
    const Vec3 s = b.size();
    const Domain polygon = Domain::polygon({b.lo, b.lo + Vec3{2 * s.x, 0, 0}, b.lo + Vec3{2 * s.x, 2 * s.y, 0},
                                            b.lo + Vec3{s.x, 1.2 * s.y, 0}, b.lo + Vec3{0, 2 * s.y, 0}});
    for (int threads : {1, 2}) {
        DetOptions o;
        o.threads = threads;
        core::reset_widest_parallel_for();
        synthesize_det(ex, polygon, o);
        EXPECT_EQ(core::widest_parallel_for(), threads);
        PcfSynthOptions p;
        p.threads = threads;
        core::reset_widest_parallel_for();
        synthesize_pcf(ex, polygon, p);
        EXPECT_LE(core::widest_parallel_for(), threads);
    }
}

TEST(DetSession, ACancelReachesIntoALongSearch) {
    // A long step re-sends its last event about every 50 ms; answering a repeat with false
    // stops the run there, inside the search, before that iteration's end.
    const Exemplar ex = test::example("poisson_disk_2d");
    DetOptions o;
    o.iterations = 3;
    o.threads = 2;
    std::vector<ProgressEvent> events;
    const Progress progress = [&](const ProgressEvent& e) {
        const bool repeat = !events.empty() && events.back().stage == e.stage &&
                            events.back().iteration == e.iteration && e.stage == "iteration";
        events.push_back(e);
        return !repeat;
    };
    EXPECT_THROW(synthesize_det(ex, ex.domain.scaled(10.0), o, progress), Cancelled);  // ~44,000 disks
    int last_iteration = -1;
    for (const ProgressEvent& e : events)
        if (e.stage == "iteration") last_iteration = std::max(last_iteration, e.iteration);
    EXPECT_LT(last_iteration, o.iterations - 1) << "the cancel waited for the end of the run";
}
