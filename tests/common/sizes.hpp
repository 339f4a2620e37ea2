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

}  // namespace momentlab::testing
