// tessera/edit.hpp — distribution editing (section 6.3 of the Discrete Element
// Textures paper): the user changes one element (its position or attributes);
// the change propagates to every element whose neighbourhood is similar to the
// edited element's under the metric of Eq. 1, within a threshold.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera {

// One element's change, as a user makes it.
struct ElementEdit {
    std::uint64_t element = 0;           // id of the edited element (Element::id)
    Vec3 offset;                         // its move
    std::optional<std::string> type;     // a new type (by name; must exist)
    std::optional<double> radius;        // a new radius (> 0)
    std::optional<double> angle;         // a new 2D orientation angle, radians
    std::map<std::string, double> attributes;  // new values of free attributes (must exist)
};

struct EditOptions {
    double radius = 0.0;     // neighbourhood radius; 0 = the synthesis default (2 or 1.5 spacings)
    // Largest neighbourhood distance (Eq. 1) of an element that receives the edit,
    // in squared length units; negative = automatic: 0.1 x spacing^2 per neighbour
    // of the edited element (neighbours displaced by about a third of a spacing).
    double threshold = -1.0;
    int threads = 0;
};

struct EditReport {
    std::vector<std::uint64_t> changed;  // ids of the changed elements, the edited one included
    double threshold = 0.0;              // the threshold used
};

// Applies `edit` to its element and to every unlocked element with a similar
// neighbourhood (locked elements are never changed). Throws Error(input) if the element,
// type or an attribute does not exist, the element is locked, or the edit is not valid
// (radius <= 0, non-finite numbers).
Exemplar edit_elements(const Exemplar& data, const ElementEdit& edit, const EditOptions& options = {},
                       EditReport* report = nullptr);

// Reads an edit file (JSON, documented in docs/format.md); `source` names it in errors.
ElementEdit parse_edit_json(const std::string& text, const std::string& source);

}  // namespace tessera
