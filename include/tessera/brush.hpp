// tessera/brush.hpp — brushing element fields (Hsu, Wei, You and Zhang, "Brushing Element
// Fields", SIGGRAPH Asia 2018 technical briefs; docs/brush.md).
//
// A BrushCanvas is an output domain (a 2D plane region, a 3D volume or a 3D surface) that a
// user paints:
// elements of one or several exemplars (the palette) are grown along a stroke next to the
// elements already there, direction strokes set the element field where the user wants it,
// an erase stroke removes elements, and fill() completes the rest of the canvas from the
// partial strokes. Every element sample carries a local orientation o(s) (a unit direction:
// the image of its exemplar's +x axis) and its element a scale c; the solver (section 5)
// alternates the neighbourhood search/assignment over positions (distribution Eq. 1-2 with
// w_scale and each sample's own exemplar kappa, conflict check Eq. 3, graph similarity Eq. 4)
// with L-BFGS over the orientations (field alignment Eq. 5, field continuity Eq. 6, element
// rigidity Eq. 7).
//
// Per element type: weighted samples (ElementType::weights, a bounding radius per sample)
// and an element graph (ElementType::graph, edges between sample ids); their defaults are
// in brush_sample_weights() and brush_element_graph().
//
// Painted elements are locked (Element::locked): later paint, fill and optimize calls never
// move or retype them; erase removes them. Deterministic: the same canvas, palette, options,
// seed and calls give the same arrangement whatever the thread count. Not thread-safe: one
// thread at a time per canvas (canvases are independent).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/progress.hpp"

namespace tessera {

struct BrushOptions {
    // Neighbourhood radius of the distribution term (Eq. 1), in units of the exemplar's mean
    // nearest-neighbour spacing (each exemplar has its own).
    double radius = 1.5;
    // Solver iterations of fill() and optimize(): each one search/assignment over positions
    // and one L-BFGS solve over the orientations.
    int iterations = 8;
    // Iterations of one L-BFGS solve (its bound; reported when hit).
    int lbfgs_iterations = 60;
    // sigma of the Gaussian falloffs of Eq. 5 and Eq. 6, in spacings.
    double sigma = 2.0;
    // Weights of the terms: distribution (Eq. 1), conflict check (Eq. 3), graph similarity
    // (Eq. 4), field alignment (Eq. 5), field continuity (Eq. 6), rigidity (Eq. 7) of
    // deformable elements (rigid elements keep one orientation exactly).
    double w_distribution = 1.0;
    double w_conflict = 4.0;
    double w_graph = 8.0;
    double w_alignment = 4.0;
    double w_continuity = 1.0;
    double w_rigidity = 2.0;
    // Width of a paint or erase stroke when the stroke gives none, in spacings.
    double stroke_width = 4.0;
    int threads = 0;  // 0 = all hardware threads; results are identical for every value
    std::uint64_t seed = 1;
};

// A stroke: a polyline drawn on the canvas (z = 0 on a plane), and for paint and erase
// strokes the width of the band it sweeps (0 = BrushOptions::stroke_width spacings).
struct Stroke {
    std::vector<Vec3> points;
    double width = 0.0;
};

// What a call did.
struct BrushReport {
    int added = 0;           // elements made
    int removed = 0;         // elements erased, or dropped in conflict with others
    int iterations = 0;      // solver iterations run
    int lbfgs_bound_hits = 0;  // L-BFGS solves stopped by BrushOptions::lbfgs_iterations
    int solve_bound_hits = 0;  // position solves stopped by their iteration bound (400)
    bool kept_earlier = false;  // the last iteration was not the best: the best state seen was kept
    double energy = 0.0;     // E_d + E_k + E_g + E_a + E_c + E_r after the call (per sample)
    double seconds = 0.0;
};

namespace brush {
class Surface;  // the surface of a surface canvas (src/brush/surface.hpp)
}

class BrushCanvas {
public:
    // A canvas over `domain`: 2D planes (box, polygon, mask), 3D volumes (box, mesh) and 3D
    // surfaces (shell). A shell canvas is a surface canvas (the paper's Figure 1b): elements sit
    // on the mesh's surface, strokes are moved onto it and the element field is tangent to it;
    // the mesh is read again from the shell's file (Error(domain) for a shell made from a mesh
    // in memory: use the constructor below). Error(option) naming the field for invalid options.
    BrushCanvas(const Domain& domain, const BrushOptions& options = {});
    // A surface canvas on a mesh in memory (counter-clockwise = outward), its domain the shell
    // Domain::shell(surface, thickness): growth runs within `thickness` of the surface (about
    // one palette spacing), and every sample is then moved onto the surface.
    BrushCanvas(const TriangleMesh& surface, double thickness, const BrushOptions& options = {},
                const std::string& name = "mesh");
    ~BrushCanvas();
    BrushCanvas(BrushCanvas&&) noexcept;
    BrushCanvas& operator=(BrushCanvas&&) noexcept;
    BrushCanvas(const BrushCanvas& other);
    BrushCanvas& operator=(const BrushCanvas&) = delete;

    // Adds an exemplar to the palette under `name` (unique) and returns its index kappa.
    // Error(input) for an exemplar of another dimension than the canvas, a name already
    // used, or invalid weights or graph.
    int add_exemplar(const std::string& name, const Exemplar& exemplar);
    // Index of a palette entry by name, or -1.
    int find_exemplar(const std::string& name) const;
    const std::vector<std::string>& palette() const;

    // Grows elements of palette entry `exemplar` along the stroke, in the band it sweeps
    // (clipped to the canvas), oriented along it, next to the elements already there; the
    // stroke also becomes a direction stroke. The new elements are locked.
    BrushReport paint(int exemplar, const Stroke& stroke);
    // A direction stroke: the element field follows it near the stroke (Eq. 5).
    BrushReport direct(const Stroke& stroke);
    // Removes the elements whose centre lies in the band the stroke sweeps.
    BrushReport erase(const Stroke& stroke);
    // Completes the canvas: each empty place is grown from the palette entry of the nearest
    // element already there (all of `exemplars` when the canvas is empty: the first one),
    // then the solver runs over every unlocked element. Error(input) if `exemplars` is
    // empty and the canvas holds no element.
    BrushReport fill(const std::vector<int>& exemplars = {});
    // The solver alone over every unlocked element (section 5).
    BrushReport optimize(int iterations);

    // Progress of the calls that follow (stage "paint", "fill", "iteration"); returning false
    // cancels: Cancelled is thrown and the canvas is as it was before the call.
    void set_progress(Progress progress);

    // The arrangement: the union of the palette entries' types (a type whose name is taken
    // by an earlier entry is named "name (entry)"), element orientations from the samples'.
    const Arrangement& arrangement() const;
    // Per sample of arrangement(): its orientation o(s) (unit) and its palette entry kappa.
    const std::vector<Vec3>& sample_directions() const;
    std::vector<int> sample_exemplars() const;
    // The direction strokes so far (paint strokes included).
    const std::vector<Stroke>& direction_strokes() const;
    const Domain& domain() const;
    const BrushOptions& options() const;

    // The energy terms of the current arrangement, per sample (for tests and reports).
    struct Energies {
        double distribution = 0, conflict = 0, graph = 0, alignment = 0, continuity = 0, rigidity = 0;
    };
    Energies energies() const;

    struct Impl;

private:
    BrushCanvas(const Domain& domain, const BrushOptions& options, std::shared_ptr<const brush::Surface> surface);
    std::unique_ptr<Impl> impl_;
};

// The weight (bounding radius) of each sample of a type: ElementType::weights when given;
// otherwise the element radius for single-sample elements with one, else half the 10%
// quantile of the distance from the type's samples to the nearest sample of another element.
std::vector<double> brush_sample_weights(const Exemplar& exemplar, int type);
// The element graph of a type: ElementType::graph when given; otherwise a chain through the
// samples in id order (none for single-sample elements).
std::vector<std::array<int, 2>> brush_element_graph(const Exemplar& exemplar, int type);

// A session file (docs/brush.md, "Session files"): the canvas, the palette, the options and
// the operations (paint, direction, erase, fill, optimize) replayed in order.
struct BrushSession {
    // A domain as --domain writes it ("box:60,40", "mesh:f.obj", "shell:f.obj,0.5"), or a
    // surface, "surface:FILE[,thickness[,resolution]]" (FILE relative to base_dir; thickness by
    // default the largest palette spacing): the shell canvas of that thickness.
    std::string canvas;
    std::string base_dir = ".";           // the session file's folder
    int dimension = 2;
    std::vector<std::string> palette_names;
    std::vector<Exemplar> palette;
    BrushOptions options;
    struct Op {
        std::string kind;                 // "paint", "direction", "erase", "fill", "optimize"
        std::vector<int> exemplars;       // paint: one; fill: any (empty = from the canvas)
        Stroke stroke;
        int iterations = 0;               // optimize
    };
    std::vector<Op> ops;
};
// Reads a session file: exemplar paths are relative to the file. Error(io) when it cannot be
// read, Error(input) naming the file and the key ("ops[2].stroke") for malformed content,
// Error(option) naming "options.NAME" for a bad option.
BrushSession read_brush_session(const std::string& path);
BrushSession parse_brush_session(const std::string& text, const std::string& source, const std::string& base_dir);
// Replays a session: the canvas after its last operation.
BrushCanvas replay_brush_session(const BrushSession& session, const Progress& progress = {});

}  // namespace tessera
