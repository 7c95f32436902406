// Topology-guided neighbourhoods (Dynamic Element Textures, section 3.2, "Topology
// constraint"): the samples of a thread or a sheet are addressed by (row, column) on their
// element's grid (a thread is one row; a particle one cell), and a neighbourhood is the block
// of grid cells around the centre, like pixels in an image (Lefebvre and Hoppe 2005), over a
// window of frames. The topology fixes which output sample pairs with which input sample, so
// these pairs need no Hungarian matching (they precede it, as the paper says).
#pragma once

#include <vector>

#include "tessera/dynamic.hpp"

namespace tessera::dynamic {

// One entry of a grid neighbourhood: a step of (dr, dc) on the element's grid and dt frames.
struct GridOffset {
    int dr = 0, dc = 0, dt = 0;
    double kappa = 1.0;  // Eq. 10 falloff of the entry about the centre
};

// Where every sample of a structure sits on its element's grid.
class TopologyGrid {
public:
    // Throws Error(input) naming `source` for multi-sample elements of topology none (rigid
    // multi-sample bodies have no grid to guide a neighbourhood).
    TopologyGrid(const Exemplar& data, const std::string& source);

    int sample_count() const { return static_cast<int>(element_.size()); }
    int element_count() const { return static_cast<int>(first_.size()); }
    int element(int s) const { return element_[s]; }
    int row(int s) const { return row_[s]; }
    int col(int s) const { return col_[s]; }
    int rows(int e) const { return rows_[e]; }
    int cols(int e) const { return cols_[e]; }
    ElementTopology kind(int e) const { return kind_[e]; }
    // The sample at (row, col) of element e, or -1 outside its grid.
    int at(int e, int r, int c) const {
        if (r < 0 || c < 0 || r >= rows_[e] || c >= cols_[e]) return -1;
        return first_[e] + r * cols_[e] + c;
    }
    // The sample (dr, dc) away from s on its element's grid, or -1.
    int step(int s, int dr, int dc) const { return at(element_[s], row_[s] + dr, col_[s] + dc); }

private:
    std::vector<int> element_, row_, col_;    // per sample
    std::vector<int> first_, rows_, cols_;    // per element
    std::vector<ElementTopology> kind_;       // per element
};

// The neighbourhood of a topology: threads (dc in [-h, h]), sheets ((dr, dc) in [-h, h]^2,
// the paper's 7 x 7 for h = 3) or particles (the centre only); frames dt in [-w, w]
// (temporal-non-causal: all frames are synthesized together). Compact shape: the spatial
// block at dt = 0 plus the centre's own trail; full: the block at every dt. The centre
// (0, 0, 0) comes first. kappa follows Eq. 10 with sigma_p in neighbourhood half-widths and
// sigma_t in frames (0 = no falloff).
std::vector<GridOffset> grid_offsets(ElementTopology kind, int half_size, int half_window, NeighbourhoodShape shape,
                                     double sigma_p, double sigma_t);

}  // namespace tessera::dynamic
