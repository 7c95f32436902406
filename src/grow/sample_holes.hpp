// Holes between multi-sample elements (grow/sample_holes.cpp).
//
// The hole passes of grow/vacancies.hpp measure holes between element centres and fill them
// with single-sample elements; exemplars of multi-sample elements (sticks, noodles) got none.
// Their candidates are dropped where none of the shapes tried fits the gap (no shape is bent
// to fit), and a grown region of noodles held 85% of the exemplar's count, with empty places
// 1.7x the exemplar's largest empty circle (measured against samples). Once a region is
// covered, every place farther from all samples than the exemplar's largest empty circle
// gets an element where one of the type's input shapes fits whole, deepest place first.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// For exemplars of multi-sample elements without a registered layer, in a closed region (not
// a world's tile): probes `region` on a
// lattice of half the exemplar's largest empty circle (the largest disk or ball free of
// samples), and puts an element into each place still emptier than that, its centroid at the
// place: of the type most short of its share, shaped as one of kShapeTries input elements of
// the type (the pool element nearest the nearest element's match first), unturned but for the
// field's frame, none of its samples closer to another element's than their sample hard core,
// inside the region. Returns how many were added (appended, fixed like the rounds' elements).
int fill_sample_holes(Grower::Impl& g, const Domain& region);

}  // namespace tessera::grow
