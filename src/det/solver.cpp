// Placeholder until the solver lands in this directory.
#include "tessera/det.hpp"
#include "tessera/error.hpp"

namespace tessera {
Arrangement synthesize_det(const Exemplar&, const Domain&, const DetOptions&, const Progress&) {
    throw Error(ErrorKind::internal, "synthesize_det is being written");
}
}  // namespace tessera
