#pragma once

/// \file
/// The checks a front end (the command line, Python, the web module) makes of the numbers a user
/// gives besides a scene, each with its one message: every number finite, 0 or of magnitude
/// kSmallestMagnitude .. kLargestMagnitude; a vector by its largest coordinate, as the scene
/// reader checks vectors (docs/formats.md, docs/robustness.md). `where` names the input in the
/// message: "--wrench" on the command line, "wrench" as a keyword. Each throws InputError.

#include <string>

#include "momentlab/core/rational.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab {

/// A number: finite, 0 or of magnitude 1e-60 .. 1e60.
[[nodiscard]] double checked_number(double x, const std::string& where);
/// A vector: finite, its largest coordinate 0 or of magnitude 1e-60 .. 1e60 (so [1, 0, 1e-61]
/// and [1, -2, 5e-324] are accepted).
[[nodiscard]] Vec2 checked_vector(const Vec2& v, const std::string& where);
[[nodiscard]] Vec3 checked_vector(const Vec3& v, const std::string& where);
/// A direction: a vector, not zero.
[[nodiscard]] Vec2 checked_direction(const Vec2& d, const std::string& where);
/// A friction coefficient: a number >= 0.
[[nodiscard]] double checked_coefficient(double mu, const std::string& where);
/// The same for an exact mu (a decimal as typed): its rounding checked.
[[nodiscard]] Rational checked_coefficient(const Rational& mu, const std::string& where);
/// A length: a number > 0.
[[nodiscard]] double checked_length(double x, const std::string& where);
/// A view box (xmin, ymin, xmax, ymax): finite, xmin < xmax and ymin < ymax, its larger side of
/// magnitude 1e-60 .. 1e60.
[[nodiscard]] Box checked_view(double xmin, double ymin, double xmax, double ymax, const std::string& where);

}  // namespace momentlab
