// The rest of a region that growth did not reach (grow/uncovered.cpp).
//
// Rounds propose only next to the horizon, from the input patch of each horizon element's
// best match. Where the exemplar's structure is wider than that patch (the gaps between the
// clusters of a clustered pattern), no candidate lands beyond it and growth stops with most
// of the region empty: a redwood exemplar grew 14 to 58 elements of the 1,240 its region
// asked for. The place where it stopped is then a hole far larger than any the exemplar
// shows. grow(region) fills such places the way synthesize_det fills a domain: patch-copy
// initialization (section 4.1 of Discrete Element Textures), its search/assign iterations
// with every element already there locked, through the same DetSession the other methods
// use. Growth of an exemplar whose horizon reaches everywhere finds no such place and pays
// one pass of the hole test.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Where a point counts as not reached: farther from every element's centre than this.
// Twice the exemplar's largest hole (rim to rim, as det::exemplar_hole_radius) plus its
// spacing: a hole a grown output may show at the quality bounds never reaches it.
// For a layered exemplar (det/layers.hpp) the distance is measured in the layer's plane: a
// region thicker than the layer is not filled above and below it (and with an orientation
// field, which turns the layer, nothing is filled).
double uncovered_distance(const Grower::Impl& g);

// Fills the parts of `region` farther than uncovered_distance from every element (`current`:
// the grower's arrangement as Grower::arrangement() shows it): returns
// the elements added (0 when growth reached everywhere). The new elements lie in the region
// (their centres, for an open region), take ids after the last, are fixed for later growth
// like the elements of an existing arrangement, and are not locked in the arrangement the
// caller sees. Progress goes to the grower's callback as stage "uncovered"; a cancel throws
// Cancelled and leaves the grower as it was.
int fill_uncovered(Grower::Impl& g, const Domain& region, const Arrangement& current);

}  // namespace tessera::grow
