#pragma once
// The sizes of the big randomized tests: in full in the release build (the counts README.md
// states and the tests assert), a sixteenth under the sanitizers (make test-sanitizers), where a
// case costs 20-40 times as much and the point is memory and undefined behaviour, not counts.
namespace momentlab::testing {

#ifdef MOMENTLAB_SANITIZED
inline constexpr int kSizeDivisor = 16;
#else
inline constexpr int kSizeDivisor = 1;
#endif

/// n cases in the release build, n / 16 under the sanitizers.
constexpr int sized(int n) { return n / kSizeDivisor; }

/// Whether the randomized tests run at their full size (the release build).
inline constexpr bool kFullSize = kSizeDivisor == 1;

/// A floor on how often a randomized test met a kind of case: n in the release build, which
/// asserts it; none under the sanitizers, whose sixteenth-size runs are too small for such counts
/// to be stable (there the point is memory and undefined behaviour).
constexpr int floor_of(int n) { return kFullSize ? n : 0; }

}  // namespace momentlab::testing
