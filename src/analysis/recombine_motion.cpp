// recombine_motion (tessera/motion_analysis.hpp): Dynamic Element Textures, section 5,
// Figures 6-7: "recombine the coarse motion of one sequence with the details of another",
// e.g. the analysed detail motion of hair on a novel coarse motion. Out = C + D, with D taken
// from another animation: frames cycle through the detail's frames, elements through the
// detail's elements of the same topology kind, and threads and sheets of another sample
// count are resampled along their index (detail_resample.hpp).
#include <array>
#include <string>

#include "analysis/detail_resample.hpp"
#include "tessera/error.hpp"
#include "tessera/motion_analysis.hpp"

namespace tessera {

namespace {

using analysis::Layout;

int kind_index(ElementTopology t) {
    return t == ElementTopology::thread ? 1 : t == ElementTopology::sheet ? 2 : 0;
}

// The elements of each topology kind (none, thread, sheet), in element order.
std::array<std::vector<int>, 3> elements_by_kind(const std::vector<Layout>& layouts) {
    std::array<std::vector<int>, 3> kinds;
    for (size_t e = 0; e < layouts.size(); ++e)
        kinds[kind_index(layouts[e].topology)].push_back(static_cast<int>(e));
    return kinds;
}

// For each element of coarse, the detail element whose offsets it takes: the i-th element of
// a kind takes the detail's (i mod count)-th of that kind, so that an animation's own details
// go back to their own elements.
std::vector<int> detail_partners(const Animation& coarse, const std::vector<Layout>& coarse_layouts,
                                 const std::vector<Layout>& detail_layouts) {
    const auto mine = elements_by_kind(coarse_layouts), theirs = elements_by_kind(detail_layouts);
    std::vector<int> partner(coarse_layouts.size(), -1);
    for (int k = 0; k < 3; ++k) {
        if (mine[k].empty()) continue;
        if (theirs[k].empty()) {
            const Element& e = coarse.structure.elements[mine[k][0]];
            const char* word = analysis::topology_word(coarse_layouts[mine[k][0]].topology);
            throw Error(ErrorKind::input, std::string("the detail animation has no ") + word +
                                              " elements for the coarse animation's " + word +
                                              " elements (type '" + coarse.structure.types[e.type].name +
                                              "')");
        }
        for (size_t i = 0; i < mine[k].size(); ++i) partner[mine[k][i]] = theirs[k][i % theirs[k].size()];
    }
    return partner;
}

void check_pair(const Animation& coarse, const Animation& detail) {
    coarse.validate("coarse animation");
    detail.validate("detail animation");
    if (coarse.structure.dimension != detail.structure.dimension)
        throw Error(ErrorKind::input,
                    "the coarse animation is " + std::to_string(coarse.structure.dimension) +
                        "D and the detail animation " + std::to_string(detail.structure.dimension) + "D");
}

}  // namespace

Animation recombine_motion(const Animation& coarse, const Animation& detail) {
    check_pair(coarse, detail);
    const std::vector<Layout> layouts = analysis::element_layouts(coarse.structure);
    const std::vector<Layout> detail_layouts = analysis::element_layouts(detail.structure);
    const std::vector<int> partner = detail_partners(coarse, layouts, detail_layouts);
    Animation out = coarse;
    const int frames = coarse.frame_count(), detail_frames = detail.frame_count();
    std::vector<Vec3> offsets;
    for (size_t e = 0; e < layouts.size(); ++e) {
        const Element& element = coarse.structure.elements[e];
        offsets.resize(static_cast<size_t>(element.sample_count));
        for (int f = 0; f < frames; ++f) {
            analysis::resampled_offsets(detail, partner[e], detail_layouts[partner[e]], f % detail_frames,
                                        layouts[e], offsets.data());
            for (int k = 0; k < element.sample_count; ++k) out.at(f, element.first_sample + k) += offsets[k];
        }
    }
    out.structure = out.frame(0);
    return out;
}

}  // namespace tessera
