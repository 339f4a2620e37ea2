#include "lp_oracle.hpp"

#include <setoper.h>
#include <cdd.h>

#include <mutex>
#include <stdexcept>

namespace momentlab::oracle {
namespace {

void init() {
    static std::once_flag once;
    std::call_once(once, [] { dd_set_global_constants(); });
}

// Row r of the LP in the variables (xi_1, xi_2, xi_3, t): b + a . x >= 0 (or = 0 if `equal`).
void set_row(dd_MatrixPtr m, long r, const QVec& a, int slack, int b, bool equal) {
    mpq_set_si(m->matrix[r][0], b, 1);
    for (int i = 0; i < 3; ++i) mpq_set(m->matrix[r][i + 1], a[static_cast<std::size_t>(i)].get_mpq_t());
    mpq_set_si(m->matrix[r][4], slack, 1);
    if (equal) set_addelem(m->linset, r + 1);
}

}  // namespace

bool realisable(const std::vector<QVec>& n, const std::vector<QVec>& t, const std::string& labels) {
    init();
    long rows = 1;  // t <= 1
    bool strict = false;
    for (char c : labels) {
        rows += c == 's' ? 1 : 2;
        strict = strict || c != 'f';
    }
    if (!strict) return true;  // xi = 0
    dd_MatrixPtr m = dd_CreateMatrix(rows, 5);
    m->representation = dd_Inequality;
    m->numbtype = dd_Rational;
    long r = 0;
    set_row(m, r++, QVec{0, 0, 0}, -1, 1, false);
    for (std::size_t j = 0; j < labels.size(); ++j) {
        switch (labels[j]) {
            case 's': set_row(m, r++, n[j], -1, 0, false); break;
            case 'f':
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, t[j], 0, 0, true);
                break;
            case 'r':
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, t[j], -1, 0, false);
                break;
            default:
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, reference::neg(t[j]), -1, 0, false);
                break;
        }
    }
    m->objective = dd_LPmax;
    for (int i = 0; i < 5; ++i) dd_set_si(m->rowvec[i], i == 4 ? 1 : 0);
    dd_ErrorType err = dd_NoError;
    dd_LPPtr lp = dd_Matrix2LP(m, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd Matrix2LP failed");
    dd_LPSolve(lp, dd_DualSimplex, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd LPSolve failed");
    const bool ok = lp->LPS == dd_Optimal && mpq_sgn(lp->optvalue) > 0;
    dd_FreeLPData(lp);
    dd_FreeMatrix(m);
    return ok;
}

bool applied_in_mode(const QMat& m, const std::vector<QVec>& n, const std::vector<QVec>& t,
                     const std::vector<std::vector<QVec>>& contact_generators,
                     const std::string& labels, const QVec& e) {
    init();
    std::vector<QVec> gens;
    for (const auto& list : contact_generators) gens.insert(gens.end(), list.begin(), list.end());
    const long k = static_cast<long>(gens.size());
    long rows = 3 + k;
    for (char c : labels) rows += c == 's' ? 1 : 2;
    const long cols = 1 + 3 + k;
    dd_MatrixPtr a = dd_CreateMatrix(rows, cols);
    a->representation = dd_Inequality;
    a->numbtype = dd_Rational;
    for (long r = 0; r < rows; ++r) {
        for (long c = 0; c < cols; ++c) dd_set_si(a->matrix[r][c], 0);
    }
    long r = 0;
    for (int i = 0; i < 3; ++i, ++r) {  // (M xi)_i - sum alpha g_i - e_i = 0
        const auto row = static_cast<std::size_t>(i);
        mpq_set(a->matrix[r][0], mpq_class(-e[row]).get_mpq_t());
        for (int j = 0; j < 3; ++j) mpq_set(a->matrix[r][1 + j], m[row][static_cast<std::size_t>(j)].get_mpq_t());
        for (long q = 0; q < k; ++q) {
            mpq_set(a->matrix[r][4 + q], mpq_class(-gens[static_cast<std::size_t>(q)][row]).get_mpq_t());
        }
        set_addelem(a->linset, r + 1);
    }
    for (long q = 0; q < k; ++q, ++r) dd_set_si(a->matrix[r][4 + q], 1);  // alpha >= 0
    auto twist_row = [&](const QVec& v, int s, bool equal) {
        for (int j = 0; j < 3; ++j) mpq_set(a->matrix[r][1 + j], mpq_class(s * v[static_cast<std::size_t>(j)]).get_mpq_t());
        if (equal) set_addelem(a->linset, r + 1);
        ++r;
    };
    for (std::size_t j = 0; j < labels.size(); ++j) {
        switch (labels[j]) {
            case 's': twist_row(n[j], 1, false); break;
            case 'f': twist_row(n[j], 1, true); twist_row(t[j], 1, true); break;
            case 'r': twist_row(n[j], 1, true); twist_row(t[j], 1, false); break;
            default: twist_row(n[j], 1, true); twist_row(t[j], -1, false); break;
        }
    }
    a->objective = dd_LPmax;
    for (long c = 0; c < cols; ++c) dd_set_si(a->rowvec[c], 0);
    dd_ErrorType err = dd_NoError;
    dd_LPPtr lp = dd_Matrix2LP(a, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd Matrix2LP failed");
    dd_LPSolve(lp, dd_DualSimplex, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd LPSolve failed");
    const bool ok = lp->LPS == dd_Optimal;
    dd_FreeLPData(lp);
    dd_FreeMatrix(a);
    return ok;
}

std::set<std::string> all_modes(const std::vector<QVec>& n, const std::vector<QVec>& t) {
    std::set<std::string> out;
    std::vector<std::string> stack = {""};
    while (!stack.empty()) {
        const std::string prefix = stack.back();
        stack.pop_back();
        if (prefix.size() == n.size()) {
            out.insert(prefix);
            continue;
        }
        for (char c : {'s', 'f', 'r', 'l'}) {
            std::string next = prefix;
            next.push_back(c);  // (prefix + c trips GCC 12's -Wrestrict false positive)
            if (realisable(n, t, next)) stack.push_back(next);
        }
    }
    return out;
}

}  // namespace momentlab::oracle
