#include "cdd_oracle.hpp"

#include "cdd_setup.hpp"

#include <stdexcept>

namespace momentlab::oracle {
namespace {

// Rows [first, x, y, z]; `first` is 1 for the origin point, 0 otherwise.
dd_MatrixPtr make(const std::vector<QVec>& rows, dd_RepresentationType rep, bool with_origin) {
    const long n = static_cast<long>(rows.size()) + (with_origin ? 1 : 0);
    dd_MatrixPtr m = dd_CreateMatrix(n, 4);
    m->representation = rep;
    m->numbtype = dd_Rational;
    long r = 0;
    if (with_origin) {
        dd_set_si(m->matrix[r][0], 1);
        for (int j = 1; j < 4; ++j) dd_set_si(m->matrix[r][j], 0);
        ++r;
    }
    for (const QVec& v : rows) {
        dd_set_si(m->matrix[r][0], 0);
        for (int j = 0; j < 3; ++j) mpq_set(m->matrix[r][j + 1], v[static_cast<std::size_t>(j)].get_mpq_t());
        ++r;
    }
    return m;
}

QVec row(dd_MatrixPtr m, long r) {
    QVec v;
    for (int j = 0; j < 3; ++j) v[static_cast<std::size_t>(j)] = mpq_class(m->matrix[r][j + 1]);
    return v;
}

bool is_zero(const QVec& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }

// Reads the computed side of a conversion: the inequalities of a V-input, or the generators
// of an H-input (the other side of dd_Copy* is the input itself, redundancy and all).
void read_inequalities(dd_MatrixPtr h, OracleCone& out) {
    for (long r = 0; r < h->rowsize; ++r) {
        const QVec v = row(h, r);
        if (is_zero(v)) continue;  // the trivial row 1 >= 0
        (set_member(r + 1, h->linset) ? out.equations : out.facets).push_back(v);
    }
    out.dimension = 3 - static_cast<int>(out.equations.size());
}

void read_generators(dd_MatrixPtr g, OracleCone& out) {
    for (long r = 0; r < g->rowsize; ++r) {
        if (mpq_sgn(g->matrix[r][0]) != 0) continue;  // the origin
        const QVec v = row(g, r);
        if (is_zero(v)) continue;
        (set_member(r + 1, g->linset) ? out.lineality : out.rays).push_back(v);
    }
    out.lineality_dimension = static_cast<int>(out.lineality.size());
}

dd_PolyhedraPtr convert(dd_MatrixPtr m) {
    dd_ErrorType err = dd_NoError;
    dd_PolyhedraPtr poly = dd_DDMatrix2Poly(m, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd DDMatrix2Poly failed");
    return poly;
}

// The double description method outputs each extreme ray or facet once, and a basis of the
// linearity, on the side it computes: converting twice gives both sides minimal.
OracleCone run(dd_MatrixPtr input, bool input_is_generators) {
    OracleCone out;
    dd_PolyhedraPtr first = convert(input);
    dd_MatrixPtr computed = input_is_generators ? dd_CopyInequalities(first) : dd_CopyGenerators(first);
    dd_PolyhedraPtr second = convert(computed);
    dd_MatrixPtr back = input_is_generators ? dd_CopyGenerators(second) : dd_CopyInequalities(second);
    if (input_is_generators) {
        read_inequalities(computed, out);
        read_generators(back, out);
    } else {
        read_generators(computed, out);
        read_inequalities(back, out);
    }
    dd_FreeMatrix(back);
    dd_FreePolyhedra(second);
    dd_FreeMatrix(computed);
    dd_FreePolyhedra(first);
    dd_FreeMatrix(input);
    return out;
}

std::vector<QVec> exact_all(const std::vector<Vec3>& vs) {
    std::vector<QVec> out;
    for (const Vec3& v : vs) out.push_back(reference::q(v));
    return out;
}

// The rank of a set of rational vectors (Gaussian elimination, exact).
int rank(std::vector<QVec> rows) {
    int r = 0;
    for (std::size_t col = 0; col < 3 && static_cast<std::size_t>(r) < rows.size(); ++col) {
        std::size_t pivot = static_cast<std::size_t>(r);
        while (pivot < rows.size() && sgn(rows[pivot][col]) == 0) ++pivot;
        if (pivot == rows.size()) continue;
        std::swap(rows[pivot], rows[static_cast<std::size_t>(r)]);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            if (i == static_cast<std::size_t>(r) || sgn(rows[i][col]) == 0) continue;
            const mpq_class f = rows[i][col] / rows[static_cast<std::size_t>(r)][col];
            for (std::size_t k = 0; k < 3; ++k) rows[i][k] -= f * rows[static_cast<std::size_t>(r)][k];
        }
        ++r;
    }
    return r;
}

}  // namespace

OracleCone from_generators(const std::vector<QVec>& generators) {
    cdd_setup();
    return run(make(generators, dd_Generator, true), true);
}

OracleCone from_generators(const std::vector<Vec3>& generators) { return from_generators(exact_all(generators)); }

OracleCone from_halfspaces(const std::vector<QVec>& normals) {
    cdd_setup();
    if (normals.empty()) {
        // cdd needs at least one row: the trivial inequality 1 >= 0.
        return run(make({}, dd_Inequality, true), false);
    }
    return run(make(normals, dd_Inequality, false), false);
}

OracleCone from_halfspaces(const std::vector<Vec3>& normals) { return from_halfspaces(exact_all(normals)); }

std::vector<std::pair<mpq_class, QVec>> hull_facets(const std::vector<Vec3>& points) {
    cdd_setup();
    dd_MatrixPtr m = dd_CreateMatrix(static_cast<long>(points.size()), 4);
    m->representation = dd_Generator;
    m->numbtype = dd_Rational;
    for (std::size_t r = 0; r < points.size(); ++r) {
        dd_set_si(m->matrix[r][0], 1);  // a point, not a ray
        for (int j = 0; j < 3; ++j) mpq_set(m->matrix[r][j + 1], mpq_class(points[r][j]).get_mpq_t());
    }
    dd_PolyhedraPtr poly = convert(m);
    dd_MatrixPtr h = dd_CopyInequalities(poly);
    std::vector<std::pair<mpq_class, QVec>> out;
    bool equations = false;
    for (long r = 0; r < h->rowsize; ++r) {
        const QVec a = row(h, r);
        if (is_zero(a)) continue;  // 1 >= 0
        equations = equations || set_member(r + 1, h->linset);
        out.emplace_back(mpq_class(h->matrix[r][0]), a);
    }
    dd_FreeMatrix(h);
    dd_FreePolyhedra(poly);
    dd_FreeMatrix(m);
    if (equations) out.clear();
    return out;
}

bool same_span(const std::vector<QVec>& a, const std::vector<QVec>& b) {
    std::vector<QVec> both = a;
    both.insert(both.end(), b.begin(), b.end());
    const int r = rank(both);
    return rank(a) == r && rank(b) == r;
}

QVec exact(const Vec3& v) { return reference::q(v); }

mpq_class dot(const QVec& a, const QVec& b) { return reference::dot(a, b); }

int sign(const mpq_class& q) { return sgn(q); }

}  // namespace momentlab::oracle
