#pragma once

/// \file
/// How an answer was found: the work counters of the exact walk and the path taken. Kept apart
/// from the answers (mechanics/advanced.hpp gives them; QueryIndex reads them to choose between
/// walking and analysing; the benchmarks print them).

#include <cstddef>

namespace momentlab {

/// The work of one answer.
struct QueryDiagnostics {
    /// True when query(scene, e)'s one-shot path (certified doubles) decided every sign; false
    /// when the exact walk answered (the counters below are then its work).
    bool filtered = false;
    /// How many modes' E e was tested against (the rest were decided by certificates).
    std::size_t built = 0;
    /// The generators of those E: with the modes walked and scanned_generators, the work of the answer.
    std::size_t tested_generators = 0;
    /// How many modes were decided by a certificate mended from the cell before (a few scans of
    /// the cell's generators with exact predicates, where testing e against E sorts them).
    std::size_t mended = 0;
    /// The generators of the cells whose certificate a mend tried (each scanned a few times).
    std::size_t scanned_generators = 0;
    /// Of the built E, how many were of cells on a face whose closed contacts' edges have few
    /// distinct forces (a floor of one mu): each such group of edges given by its two of least
    /// and greatest torque, updated from the cell before in O(log n) a contact that changed.
    std::size_t grouped = 0;
    /// The closed contacts summed over the modes (the letters that are not 's'): about the
    /// generators an analysis of the scene builds.
    std::size_t closed_letters = 0;
};

}  // namespace momentlab
