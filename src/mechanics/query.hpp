// The parts of query(scene, e) and QueryIndex that are not public: the one-shot path, and an
// exact walk's answer put in the canonical order. Internal to the mechanics layer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "momentlab/mechanics/advanced.hpp"

namespace momentlab::detail {

/// The letters of the modes whose E holds e, sorted, found in double arithmetic with certified
/// error bounds (one_shot.cpp); none when the scene has not 2 to 12 contacts or some sign is not
/// certified (then the exact walk answers). The scene and e are checked by the caller.
[[nodiscard]] std::optional<std::vector<std::string>> one_shot(const Scene& scene, const Vec3& e, bool quasi_static);

/// The walk's answer as a QueryAnswer: its modes' letters sorted, their twists alongside.
[[nodiscard]] QueryAnswer canonical(SceneAnswer&& answer);

}  // namespace momentlab::detail
