// Reading a scene file, side by side (the decision in src/io/json_read.hpp): this project's
// reader of plain JSON, nlohmann-json's SAX parser, nlohmann-json's DOM, and simdjson's
// on-demand parser (3.0.1, Debian's; a shared library only, so not in the WebAssembly build).
// Each does the whole job on the same text: a Document as the scene's Schema keeps it (numbers
// with their text, duplicate keys and underflows refused with their path), then the same
// scene-building code (json_read::scene_of; read_scene for the DOM, through document_of). A
// fifth row runs nlohmann's SAX parser with no document at all: its lexer alone.
//
// Time is wall time per read; "peak_MB" the most heap in use during a read beyond what was in
// use before it (operator new replaced here, so the libraries' allocations count too), the
// Scene included, the text not.
//
// Usage: python3 tools/families.py DIR tangent N (N = 1000, 10000, 100000), then
//        bench_io [benchmark flags] DIR
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <simdjson.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <new>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/json_read.hpp"
#include "momentlab/io/scene_json.hpp"

// Heap in use, and its peak, counted by operator new and delete.
namespace {
std::atomic<std::size_t> g_in_use{0};
std::atomic<std::size_t> g_peak{0};

void* counted(void* p) {
    if (p == nullptr) return nullptr;
    const std::size_t now = g_in_use += malloc_usable_size(p);
    for (std::size_t peak = g_peak; now > peak && !g_peak.compare_exchange_weak(peak, now);) {
    }
    return p;
}

void uncounted(void* p) {
    if (p == nullptr) return;
    g_in_use -= malloc_usable_size(p);
    std::free(p);
}

void* allocate(std::size_t n) {
    if (void* p = counted(std::malloc(n == 0 ? 1 : n))) return p;
    throw std::bad_alloc();
}

void* allocate(std::size_t n, std::align_val_t a) {
    if (void* p = counted(std::aligned_alloc(static_cast<std::size_t>(a), (n + static_cast<std::size_t>(a) - 1) /
                                                                               static_cast<std::size_t>(a) * static_cast<std::size_t>(a)))) {
        return p;
    }
    throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted(std::malloc(n == 0 ? 1 : n)); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted(std::malloc(n == 0 ? 1 : n)); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, a); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }
void operator delete(void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { uncounted(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { uncounted(p); }

namespace momentlab {
namespace {

using json_read::Builder;
using nlohmann::json;

// simdjson's on-demand values, in document order, to the builder.
void walk(simdjson::ondemand::value v, Builder& b) {
    using simdjson::ondemand::json_type;
    switch (v.type()) {
        case json_type::object:
            b.start_object();
            for (auto member : v.get_object()) {
                // (simdjson 3.0's field has no escaped_key(): every key is copied, as with nlohmann.)
                b.key(member.unescaped_key(), Builder::Text::Transient);
                walk(member.value(), b);
            }
            b.end_object();
            return;
        case json_type::array:
            b.start_array();
            for (auto element : v.get_array()) walk(element.value(), b);
            b.end_array();
            return;
        case json_type::number: {
            std::string_view text = v.raw_json_token();
            while (!text.empty() && (text.back() == ' ' || text.back() == '\n' || text.back() == '\r' || text.back() == '\t')) {
                text.remove_suffix(1);
            }
            b.number(v.get_double(), text, Builder::Text::Lasting);
            return;
        }
        case json_type::string: b.string(v.get_string(), Builder::Text::Transient); return;
        case json_type::boolean: b.boolean(v.get_bool()); return;
        case json_type::null:
            (void)v.is_null();
            b.null();
            return;
    }
}

Scene read_by_simdjson(const std::string& text) {
    simdjson::ondemand::parser parser;
    Builder b(json_read::scene_schema(), text);
    try {
        // The text was made with room for simdjson's padding: no copy.
        simdjson::ondemand::document doc = parser.iterate(simdjson::padded_string_view(text.data(), text.size(), text.capacity()));
        walk(doc.get_value(), b);
    } catch (const simdjson::simdjson_error& e) {
        throw InputError("$", std::string("malformed JSON: ") + e.what());
    }
    return json_read::scene_of(b.finish(), nullptr);
}

// The library's SAX events dropped: its lexer and parser alone.
struct NoDocument {
    bool null() { return true; }
    bool boolean(bool) { return true; }
    bool number_integer(json::number_integer_t) { return true; }
    bool number_unsigned(json::number_unsigned_t) { return true; }
    bool number_float(json::number_float_t, const json::string_t&) { return true; }
    bool string(json::string_t&) { return true; }
    bool binary(json::binary_t&) { return true; }
    bool start_object(std::size_t) { return true; }
    bool key(json::string_t&) { return true; }
    bool end_object() { return true; }
    bool start_array(std::size_t) { return true; }
    bool end_array() { return true; }
    template <class Exception>
    bool parse_error(std::size_t, const std::string&, const Exception&) {
        return false;
    }
};

const std::vector<std::pair<std::string, std::function<std::size_t(const std::string&)>>>& readers() {
    static const std::vector<std::pair<std::string, std::function<std::size_t(const std::string&)>>> kReaders = {
        {"this_reader", [](const std::string& t) { return read_scene_text(t).contacts.size(); }},
        {"nlohmann_sax",
         [](const std::string& t) {
             return json_read::scene_of(json_read::read_by_library(t, json_read::scene_schema()), nullptr).contacts.size();
         }},
        {"nlohmann_dom", [](const std::string& t) { return read_scene(json::parse(t)).contacts.size(); }},
        {"simdjson_ondemand", [](const std::string& t) { return read_by_simdjson(t).contacts.size(); }},
        {"nlohmann_sax_no_document",
         [](const std::string& t) {
             NoDocument events;
             return static_cast<std::size_t>(json::sax_parse(t, &events));
         }},
    };
    return kReaders;
}

void read(benchmark::State& state, const std::string& text, const std::function<std::size_t(const std::string&)>& reader) {
    std::size_t peak = 0;
    for (auto _ : state) {
        const std::size_t before = g_in_use;
        g_peak = before;
        benchmark::DoNotOptimize(reader(text));
        peak = std::max(peak, g_peak - before);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
    state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
}

}  // namespace
}  // namespace momentlab

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: bench_io [benchmark flags] DIR (with DIR/tangent_N.json from tools/families.py)\n");
        return 2;
    }
    std::vector<std::string> texts;
    for (const int n : {1000, 10000, 100000}) {
        const std::string path = std::string(argv[1]) + "/tangent_" + std::to_string(n) + ".json";
        std::ifstream in(path);
        if (!in) {
            std::fprintf(stderr, "bench_io: no %s (python3 tools/families.py %s tangent %d)\n", path.c_str(), argv[1], n);
            return 2;
        }
        std::ostringstream s;
        s << in.rdbuf();
        std::string text = s.str();
        text.reserve(text.size() + simdjson::SIMDJSON_PADDING);  // simdjson reads past the end
        texts.push_back(std::move(text));
    }
    for (const auto& [name, reader] : momentlab::readers()) {
        for (std::size_t k = 0; k < texts.size(); ++k) {
            const std::string label = "read/" + name + "/" + std::to_string(std::size_t{1000} * (k == 0 ? 1 : k == 1 ? 10 : 100));
            benchmark::RegisterBenchmark(label.c_str(), [&text = texts[k], &r = reader](benchmark::State& state) {
                momentlab::read(state, text, r);
            })->Unit(benchmark::kMillisecond);
        }
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
