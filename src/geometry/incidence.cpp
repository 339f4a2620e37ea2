// Facet-ray incidences (geometry/cone.hpp, Incidence), stored as compressed rows: while every
// row has the same length (the two rays of each facet of a pointed cone) only the indices are
// stored, one allocation; rows of different lengths add their offsets. Row j is
// indices_[offsets_[j], offsets_[j + 1]), or indices_[j * stride_, (j + 1) * stride_) while
// offsets_ is empty. The cyclic incidence of a pointed cone of up to kShared facets keeps no
// indices (cyclic_): its rows are read from tables shared by all cones, so that a cone built
// from a cycle of extreme rays allocates nothing for its incidence.
#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "momentlab/geometry/cone.hpp"

namespace momentlab {
namespace {

// The rows of cyclic incidences of up to kShared facets: steps[2j, 2j + 2) = {j, j + 1} and
// last[2j, 2j + 2) = {0, j}.
constexpr std::size_t kShared = 1024;
struct CyclicTables {
    std::array<int, 2 * kShared> steps{}, last{};
    constexpr CyclicTables() {
        for (std::size_t j = 0; j < kShared; ++j) {
            steps[2 * j] = static_cast<int>(j);
            steps[2 * j + 1] = static_cast<int>(j + 1);
            last[2 * j + 1] = static_cast<int>(j);
        }
    }
};
constexpr CyclicTables kCyclic;

}  // namespace

std::span<const int> Incidence::row(std::size_t j) const {
    if (cyclic_) {
        // Rows 0 .. k-2 are {j, j + 1}; the last is {0, k - 1}.
        const auto k = static_cast<std::size_t>(rows_);
        return {j + 1 < k ? kCyclic.steps.data() + 2 * j : kCyclic.last.data() + 2 * (k - 1), 2};
    }
    if (offsets_.empty()) return {indices_.data() + j * static_cast<std::size_t>(stride_), static_cast<std::size_t>(stride_)};
    return {indices_.data() + offsets_[j], static_cast<std::size_t>(offsets_[j + 1] - offsets_[j])};
}

void Incidence::add_row(std::span<const int> rays) {
    if (cyclic_) {  // the shared rows copied into indices_ first
        std::vector<int> rows;
        rows.reserve(2 * static_cast<std::size_t>(rows_) + rays.size());
        for (std::size_t j = 0; j < size(); ++j) {
            for (int i : row(j)) rows.push_back(i);
        }
        indices_ = std::move(rows);
        cyclic_ = false;
    }
    const int length = static_cast<int>(rays.size());
    if (offsets_.empty() && rows_ > 0 && length != stride_) {  // lengths differ from now on
        offsets_.reserve(static_cast<std::size_t>(rows_) + 2);
        for (int j = 0; j <= rows_; ++j) offsets_.push_back(j * stride_);
    }
    if (rows_ == 0) stride_ = length;
    indices_.insert(indices_.end(), rays.begin(), rays.end());
    if (!offsets_.empty()) offsets_.push_back(static_cast<int>(indices_.size()));
    ++rows_;
}

Incidence Incidence::transposed(std::size_t columns) const {
    std::vector<int> count(columns + 1, 0);
    for (std::size_t j = 0; j < size(); ++j) {
        for (int i : row(j)) ++count[static_cast<std::size_t>(i) + 1];
    }
    Incidence t;
    t.offsets_.assign(columns + 1, 0);
    for (std::size_t c = 0; c < columns; ++c) t.offsets_[c + 1] = t.offsets_[c] + count[c + 1];
    t.indices_.resize(static_cast<std::size_t>(t.offsets_[columns]));
    t.rows_ = static_cast<int>(columns);
    std::vector<int> fill(t.offsets_.begin(), t.offsets_.end() - 1);
    for (std::size_t j = 0; j < size(); ++j) {
        for (int i : row(j)) t.indices_[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = static_cast<int>(j);
    }
    return t;
}

Incidence Incidence::cyclic(std::size_t k) {
    Incidence c;
    c.rows_ = static_cast<int>(k);
    c.stride_ = 2;
    if (k <= kShared) {
        c.cyclic_ = true;
        return c;
    }
    c.indices_.resize(2 * k);
    for (std::size_t i = 0; i + 1 < k; ++i) {
        c.indices_[2 * i] = static_cast<int>(i);
        c.indices_[2 * i + 1] = static_cast<int>(i + 1);
    }
    c.indices_[2 * k - 2] = 0;  // the last facet: rays 0 and k - 1, increasing
    c.indices_[2 * k - 1] = static_cast<int>(k - 1);
    return c;
}

}  // namespace momentlab
