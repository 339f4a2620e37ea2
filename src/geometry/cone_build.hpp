#pragma once

#include <span>

#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// Builds the minimal double description of cone(generators) (private to the geometry layer).
struct ConeBuilder {
    static Cone build(std::span<const Vec3> generators);
};

}  // namespace momentlab
