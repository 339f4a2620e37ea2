// The cells of the contact-mode arrangement, face by face, with sparse letters: what
// enumerate_modes writes out and query_scene decides, without a string of n letters per cell.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/mechanics/modes.hpp"

namespace momentlab::detail {

/// A mode's letters for all n contacts from its closed contacts (increasing) and their letters:
/// 's' for every other contact.
[[nodiscard]] inline std::string all_letters(std::span<const int> closed, std::span<const char> letters, std::size_t n) {
    if (closed.size() == n) return {letters.begin(), letters.end()};  // (every contact closed, in order)
    std::string s(n, letter(ContactMode::Separating));
    for (std::size_t t = 0; t < closed.size(); ++t) s[static_cast<std::size_t>(closed[t])] = letters[t];
    return s;
}

/// One cell of the arrangement inside a face of A = {xi : N_j . xi >= 0}.
struct WalkCell {
    /// The mode's index in enumerate_modes' order; 0 for a cell whose letters are all 'f' (it
    /// joins the mode of xi = 0, which is mode 0 and is not itself a cell).
    std::size_t index = 0;
    /// The face (an index into the walk's faces, A.faces() order).
    std::size_t face = 0;
    /// Generators of the cell's closure (rays; a line as +-). Empty for the interior of a
    /// full-dimensional A when there are contacts (no contact closed): that closure is A itself,
    /// feasible_twists(), not listed again.
    const std::vector<Exact3>* closure = nullptr;
    /// The contacts closed on the face (N_j . xi = 0 there), increasing; every other contact
    /// separates ('s').
    std::span<const int> closed;
    /// letters[t] is the letter of contact closed[t]: 'f', 'r' or 'l'.
    std::span<const char> letters;
    /// The positions t whose letter differs from the previous cell's; only when `first` is false.
    std::span<const int> changed;
    /// The first cell of its face: nothing to compare with.
    bool first = true;

    /// The mode's letters for all n contacts ('s' for those not closed).
    [[nodiscard]] std::string all_letters(std::size_t n) const { return detail::all_letters(closed, letters, n); }
};

/// Walks the faces of A in the order of A.faces() and, inside each, its cells: a 2-D face in
/// angular order, where consecutive cells differ by the contacts whose line T_j . xi = 0 bounds
/// them. Which contacts are closed on each face is found in O(n log n) for a full-dimensional
/// pointed A (each N_j located among the extreme rays of A*), and by testing every contact on
/// every face otherwise (A then has at most four faces of dimension >= 1).
class ModeWalk {
public:
    /// How the closed contacts of each face are found: by locating each N_j among A's facet
    /// normals (possible when A is full-dimensional and pointed), by testing each contact on each
    /// face, or (Auto) by testing when A has at most 16 faces and locating otherwise. Tests force
    /// one way to compare them.
    enum class Closed { Auto, Locate, Test };
    explicit ModeWalk(const std::vector<Contact>& contacts, Closed how = Closed::Auto);
    /// A.
    [[nodiscard]] const Cone& feasible_twists() const { return a_; }
    /// Calls visit for every cell; returns the number of modes (the all-f mode included).
    std::size_t run(const Progress& progress, const std::function<void(const WalkCell&)>& visit) const;
    /// The number of faces of A (the walk's units).
    [[nodiscard]] std::size_t faces() const { return faces_.size(); }
    /// A lower bound on the number of modes, before any walk: the all-f mode, and one for each
    /// 2-D face of A. Such a face holds a 2-D cell that is not all 'f': a contact closed on it
    /// (N_j . xi = 0 on the face) slides on all of it but a line, as T_j is not a multiple of N_j.
    [[nodiscard]] std::size_t modes_at_least() const {
        return 1 + static_cast<std::size_t>(std::count_if(faces_.begin(), faces_.end(), [](const Face& f) { return f.dimension == 2; }));
    }
    /// Walks faces begin .. end - 1 only, with each cell's index counted within its face (from 1;
    /// 0 still for the all-f cells); counts[i] becomes face i's number of modes. The modes of
    /// face i are numbered after those of the faces before it, so ranges walked apart (on two
    /// threads: run_faces is const and shares nothing it writes) are numbered afterwards.
    void run_faces(std::size_t begin, std::size_t end, const Progress& progress, std::vector<std::size_t>& counts,
                   const std::function<void(const WalkCell&)>& visit) const;

private:
    std::vector<std::vector<int>> closed_sets(const std::vector<Face>& faces, Closed how) const;

    std::vector<ExactVector> normals_, tangents_;
    Cone a_;
    std::vector<Exact3> lineality_;
    std::vector<Face> faces_;
    std::vector<std::vector<int>> closed_;  // per face, the closed contacts (increasing)
};

}  // namespace momentlab::detail
