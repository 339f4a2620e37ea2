// 5^k for k = 0..27 (5^27 < 2^63): the steps in which decimal exponents are taken exactly
// (core/rational.cpp, io/plain_json.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace momentlab::detail {

inline constexpr std::array<std::uint64_t, 28> kPowersOfFive = [] {
    std::array<std::uint64_t, 28> fives{};
    fives[0] = 1;
    for (std::size_t k = 1; k < fives.size(); ++k) fives[k] = fives[k - 1] * 5;
    return fives;
}();

}  // namespace momentlab::detail
