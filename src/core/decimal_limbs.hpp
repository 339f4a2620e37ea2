// Decimal digits as base-10^9 limbs, least significant first (core/rational.cpp,
// io/plain_json.cpp: long decimal texts against doubles).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace momentlab::detail {

// The value of eight decimal digits, in three multiplications: the bytes less '0' read as one
// little-endian word, then neighbouring digits, pairs and quadruples combined (each step
// multiplies a lane by its weight and adds the next lane in the same product; Lemire, "Quickly
// parsing eight digits", 2018).
inline std::uint32_t eight_digits(const char* p) {
    std::uint64_t v = 0;
    std::memcpy(&v, p, 8);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
    v -= 0x3030303030303030;
    v = (v * 10 + (v >> 8)) & 0x00ff00ff00ff00ff;    // 2-digit lanes
    v = (v * 100 + (v >> 16)) & 0x0000ffff0000ffff;  // 4-digit lanes
    return static_cast<std::uint32_t>((v * 10000 + (v >> 32)) & 0xffffffff);
}

// The integer of `length` decimal digits into `limbs` (room for length / 9 + 1), nine digits a
// limb from the last; returns the number of limbs.
inline std::size_t limbs_of_digits(const char* digits, std::size_t length, std::uint32_t* limbs) {
    std::size_t size = 0;
    std::size_t last = length;
    for (; last >= 9; last -= 9) limbs[size++] = static_cast<std::uint32_t>(digits[last - 9] - '0') * 100000000 + eight_digits(digits + last - 8);
    if (last > 0) {
        std::uint32_t limb = 0;
        for (std::size_t i = 0; i < last; ++i) limb = limb * 10 + static_cast<std::uint32_t>(digits[i] - '0');
        limbs[size++] = limb;
    }
    return size;
}

}  // namespace momentlab::detail
