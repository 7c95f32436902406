// tessera/tessera.hpp — umbrella header: the whole public API.
#pragma once

#include "tessera/det.hpp"
#include "tessera/domain.hpp"
#include "tessera/edit.hpp"
#include "tessera/error.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/field.hpp"
#include "tessera/geometry.hpp"
#include "tessera/io.hpp"
#include "tessera/mesh.hpp"
#include "tessera/metrics.hpp"
#include "tessera/physics.hpp"
#include "tessera/progress.hpp"
#include "tessera/render.hpp"
#include "tessera/vec.hpp"
#include "tessera/version.hpp"
