// tessera/field.hpp — local orientation fields (section 5 of the Discrete Element
// Textures paper, Eq. 7): at every point of the output a local frame o(p) in
// which the exemplar's pattern is laid down. Synthesis measures neighbourhoods in
// the local frame (p^ = o(s)^-1 (p(s') - p(s))), rotates predictions and copied
// patches by it, and records each element's orientation relative to it.
//
// A field gives a direction d(p); the frame maps the exemplar's +x axis onto d(p)
// (in 3D with the least twist about it, keeping the frame's z as close to +z as
// possible). Where d(p) is (numerically) zero — the centre of a vortex — the frame
// is the identity; `degenerate_points()` of a sample set reports how often.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera {

class OrientationField {
public:
    enum class Kind { none, constant, radial, vortex, polyline };

    // No field: the global frame everywhere (the default).
    OrientationField() = default;
    // The same direction everywhere. Throws Error(option) for a zero or non-finite direction.
    static OrientationField constant(const Vec3& direction);
    // Directions pointing away from `center` (in 3D, away from the axis through center along `axis`).
    static OrientationField radial(const Vec3& center, const Vec3& axis = {0, 0, 1});
    // Directions circling `center` counter-clockwise about `axis` (2D: about +z).
    static OrientationField vortex(const Vec3& center, const Vec3& axis = {0, 0, 1});
    // The tangent of the nearest segment of a polyline (at least 2 points): a flow
    // along a curve. Throws Error(option) for fewer than 2 points, zero-length
    // segments or non-finite points.
    static OrientationField polyline(const std::vector<Vec3>& points);
    // The trefoil knot (the paper's Figure 10j) as a closed polyline of `samples`
    // points: (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) * scale + center.
    static OrientationField trefoil(const Vec3& center, double scale, int samples = 360);
    // Parses "constant:dx,dy[,dz]", "radial:cx,cy[,cz]", "vortex:cx,cy[,cz]",
    // "polyline:x1,y1[,z1],x2,y2[,z2],..." or (3D) "trefoil:cx,cy,cz,scale" (CLI --field).
    // `parameter` names the option in errors.
    static OrientationField parse(const std::string& text, int dimension, const std::string& parameter);

    Kind kind() const { return kind_; }
    bool active() const { return kind_ != Kind::none; }
    // Unit direction at p, or the zero vector where the field is degenerate.
    Vec3 direction(const Vec3& p) const;
    // Local frame at p: a rotation taking the exemplar's axes to the local axes.
    Quat frame(const Vec3& p, int dimension) const;
    std::string describe() const;

private:
    Kind kind_ = Kind::none;
    Vec3 vector_;  // constant: the direction; radial/vortex: the centre
    Vec3 axis_{0, 0, 1};
    std::vector<Vec3> points_;  // polyline
};

// Rotation taking +x onto the unit vector d (2D: about z; 3D: least twist, +z kept up).
Quat frame_from_direction(const Vec3& d, int dimension);

}  // namespace tessera
