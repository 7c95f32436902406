// brush/canvas_surface.hpp — what a surface canvas (the paper's Figure 1b) asks of the canvas:
// samples kept on the surface, orientations o(s) kept in its tangent plane, strokes snapped
// onto it, and fields turned into mesh-vertex fields whose frames have z = the normal. Every
// function leaves a plane or volume canvas (no surface) as it is.
#pragma once

#include <string>
#include <vector>

#include "brush/brush_state.hpp"
#include "tessera/field.hpp"

namespace tessera::brush {

// The surface of a shell canvas: its mesh read again from the shell's file (scaled as the
// shell is), the band as thick as the shell. Error(domain) for a shell made from a mesh in
// memory (BrushCanvas(mesh, thickness) takes the mesh itself).
std::shared_ptr<const Surface> surface_of_shell(const Domain& shell);

// Moves the samples of the elements [first, last) (the unlocked ones among them; all when
// `include_locked`) onto the surface and makes their o(s) tangent there: a rigid element's
// one orientation tangent at its centre (its samples keep identical orientations, Eq. 7 with
// w_r = infinity), a deformable element's at each sample.
void snap_elements(BrushCanvas::Impl& state, int first, int last, bool include_locked = false);

// A stroke on a surface: its segments divided into steps of at most `step`, each point moved
// onto the surface, repeated points dropped (a chord between sparse points would cut through
// the inside). Error(input) naming `where` when fewer than `min_points` distinct points remain.
Stroke snap_stroke(const BrushCanvas::Impl& state, const Stroke& stroke, double step, int min_points,
                   const std::string& where);

// `field` as growth on the canvas needs it: on a surface, its mesh-vertex form (brush/surface.hpp).
OrientationField canvas_field(const BrushCanvas::Impl& state, const OrientationField& field);

// The frame with x = d at p: on a surface z is the normal there (x made tangent).
Quat frame_at(const BrushCanvas::Impl& state, const Vec3& d, const Vec3& p);

// The direction `d` made tangent at p (on a surface; else d).
Vec3 tangent_at(const BrushCanvas::Impl& state, const Vec3& d, const Vec3& p);

}  // namespace tessera::brush
