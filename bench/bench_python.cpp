// bench_python: the Python module's batch query beside the numpy expression a Python user would
// write for the cheapest comparable question, in one embedded interpreter and one run
// (docs/benchmarks.md): `analysis.query(W)` for N = 10^6 wrenches on a 4-contact scene against
// `W @ P > 0` with P of shape (3, 32), 32 plane signs per wrench. `make bench` prints the ratio.
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

#include <cstdio>
#include <map>
#include <string>

namespace py = pybind11;

namespace {

// The scene, wrenches and planes, made once in the interpreter's globals.
const char* kSetup = R"(
import sys
sys.path.insert(0, PACKAGE_DIR)
import numpy as np
import momentlab as ml
rng = np.random.default_rng(4)
# 4 contacts under a box on the lower half of an ellipse, normals roughly towards its centre
# (the scenes of bench_contact's BM_query).
angles = np.pi * (1.0 + rng.random(4))
points = np.stack([0.5 + 0.6 * np.cos(angles), 0.25 + 0.4 * np.sin(angles)], axis=1)
normals = np.array([0.5, 0.25]) - points + 0.3 * rng.random((4, 2)) - 0.15
scene = ml.Scene(body=ml.Body(1.0, (0.5, 0.25), 0.1), contacts=ml.contacts(points, normals, 0.1 + rng.random(4)))
analysis = ml.analyze(scene)
W = 20.0 * rng.random((1_000_000, 3)) - 10.0
P = rng.normal(size=(3, 32))
)";

// Kept for the whole run and never destroyed: it must not outlive the interpreter's end.
py::dict& globals() {
    static py::dict* g = [] {
        auto* d = new py::dict(py::globals());
        (*d)["PACKAGE_DIR"] = MOMENTLAB_PYTHON_PACKAGE_PARENT;
        py::exec(kSetup, *d);
        return d;
    }();
    return *g;
}

void run(benchmark::State& state, const char* statement) {
    py::dict& g = globals();
    const py::module_ builtins = py::module_::import("builtins");
    const py::object code = builtins.attr("compile")(statement, "<bench>", "exec");
    const py::object exec = builtins.attr("exec");
    for (auto _ : state) exec(code, g);
    state.SetItemsProcessed(state.iterations() * 1'000'000);
    state.counters["modes"] = g["analysis"].attr("__len__")().cast<double>();
}

void BM_python_query_batch(benchmark::State& state) { run(state, "hits = analysis.query(W)"); }
BENCHMARK(BM_python_query_batch)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_numpy_plane_signs(benchmark::State& state) { run(state, "signs = W @ P > 0"); }
BENCHMARK(BM_numpy_plane_signs)->Unit(benchmark::kMillisecond)->UseRealTime();

class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            seconds[r.benchmark_name()] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    py::scoped_interpreter interpreter;
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const auto q = reporter.seconds.find("BM_python_query_batch/real_time");
    const auto n = reporter.seconds.find("BM_numpy_plane_signs/real_time");
    if (q != reporter.seconds.end() && n != reporter.seconds.end()) {
        std::printf("\n10^6 wrenches, 4 contacts: analysis.query(W) %.1f ms, W @ P > 0 (32 planes) %.1f ms: ratio %.2f\n",
                    1e3 * q->second, 1e3 * n->second, q->second / n->second);
    }
    benchmark::Shutdown();
    return 0;
}
