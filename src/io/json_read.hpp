#pragma once

/// \file
/// Reading JSON for the scene and force-set readers: text -> Document -> checked values, every
/// failure an InputError naming the JSON path ("$.contacts[2].mu").
///
/// A Document keeps what its Schema names and only the kind (and element count) of anything
/// else, so reading holds memory for the fields a reader uses, not for the text: an unknown
/// field of 300 MB costs one node. Each number keeps its text as typed beside its double
/// (JsonNumber), so that it can be read exactly (exact_decimal: 0.1 is 1/10).
///
/// The reader here reads the plain JSON that programs write (ASCII strings without escapes,
/// numbers that convert to finite doubles) in one pass; any other text (escapes, non-ASCII, a
/// BOM, malformed JSON, 1e400) goes to nlohmann-json's SAX parser, which feeds the same
/// document builder and words the errors. Both reject a repeated key and a number that
/// underflows to 0, naming its path. The decision to keep a reader of our own, measured side
/// by side with nlohmann's SAX and DOM readers and simdjson 3.0.1 on scenes of 10^3 .. 10^5
/// contacts (bench/bench_io.cpp; `bench_io DIR` after `python3 tools/families.py DIR tangent N`,
/// the whole job: document, scene, paths), in time and peak memory per read, against this reader:
///
///   contacts   this reader   nlohmann SAX   nlohmann DOM   simdjson on-demand (not in WebAssembly)
///   10^3       1             see the report of the commit (bench_io)
///
/// nlohmann's SAX parser alone (no document) takes longer than this reader's whole job, and
/// simdjson ships only a shared library (no WebAssembly build): the reader stays for speed.
/// O(text) time; memory O(kept values), 24 bytes a node, beside the text.

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "momentlab/core/rational.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab {
struct BodyValues;
struct Contact;
struct Scene;
}

namespace momentlab::json_read {

/// A number as it was given: its value rounded to the nearest double and its characters as typed
/// (JSON's number grammar). The text is empty for a number that was never text (a double of a
/// document built in memory, from Python or C++): its exact value is the double.
struct JsonNumber {
    double value = 0.0;
    std::string_view text;
    /// Whether the text spells `value` exactly, when the reader found out while reading it (the
    /// plain reader does for texts of at most 19 digits and for texts of any length whose
    /// exponent, as digits 10^e, is negative); Unknown otherwise.
    enum class Spelling : std::uint8_t { Unknown, Exact, Inexact } spelling = Spelling::Unknown;
};

/// A decimal exactly: (-1)^negative x digits x 10^exponent, with digits free of leading and
/// trailing zeros ("" and not negative for zero), so that equal values are equal Decimals.
struct Decimal {
    bool negative = false;
    std::string digits;
    std::int64_t exponent = 0;
    bool operator==(const Decimal&) const = default;
};

/// The exact value of a number's text in JSON's grammar, -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?,
/// with any number of digits ("0.1" is 1 x 10^-1, "1e-400" is 1 x 10^-400); nullopt for any
/// other text and for an exponent of more than 18 digits (such a number is 0 or infinite as a
/// double and is refused by the readers anyway).
[[nodiscard]] std::optional<Decimal> exact_decimal(std::string_view text);

/// What a reader keeps of a document: at each place, the members of an object and the elements
/// of an array it reads. Anything else is kept as its kind and element count alone (skipped):
/// an object where no members are named, an array where no elements are, an array longer than
/// max_elements, and every value of a member not named.
struct Schema {
    struct Member {
        std::string_view key;
        const Schema* schema;
    };
    std::span<const Member> members;   ///< an object here keeps these members
    const Schema* elements = nullptr;  ///< an array here keeps its elements so (nullptr: arrays skipped)
    std::size_t max_elements = std::numeric_limits<std::size_t>::max();
    const Schema* others = nullptr;    ///< an object here keeps its other members so (nullptr: skipped)
};
/// A place for a number, a string or a literal (containers skipped).
inline constexpr Schema kScalar{};
/// [x, y] and [a, b, c]: at most two or three scalars (a longer array is skipped).
inline constexpr Schema kPair{{}, &kScalar, 2};
inline constexpr Schema kTriple{{}, &kScalar, 3};
/// Lists of them.
inline constexpr Schema kPairs{{}, &kPair};
inline constexpr Schema kTriples{{}, &kTriple};
/// Everything (the tests' documents).
extern const Schema kEverything;

enum class Kind : std::uint8_t { Null, False, True, Number, String, Array, Object, Key };

class Document;

/// One value of a document in 16 bytes, in document order (a container's contents follow it; an
/// object's members are a Key node, then the value's nodes).
class Node {
public:
    [[nodiscard]] Kind kind() const { return static_cast<Kind>(tag_ & 7u); }
    [[nodiscard]] bool skipped() const { return (tag_ & kSkipped) != 0; }

private:
    friend class Builder;
    friend class Document;
    friend class Value;
    static constexpr std::uint32_t kSkipped = 8, kCopied = 16, kExact = 32, kInexact = 64, kLengthShift = 7;

    // No initialisers: a new block of nodes is not written (nor its pages touched) until used.
    union {
        double number_;            // Number: its value
        std::uint32_t pair_[2];    // String, Key: where its text is, its length; Array, Object: end, size
    };
    std::uint32_t text_;           // Number: where its text is
    std::uint32_t tag_;            // the kind, kSkipped, kCopied (the text is a copy), the number's
                                   // Spelling (kExact, kInexact), a number text's length
};

/// A value of a Document (a handle: valid while the document and the text it was read from are).
class Value {
public:
    Value(const Document& doc, std::size_t index) : doc_(&doc), index_(index) {}

    [[nodiscard]] Kind kind() const { return node().kind(); }
    [[nodiscard]] bool is_object() const { return kind() == Kind::Object; }
    [[nodiscard]] bool is_array() const { return kind() == Kind::Array; }
    [[nodiscard]] bool is_number() const { return kind() == Kind::Number; }
    [[nodiscard]] bool is_string() const { return kind() == Kind::String; }
    /// "null", "boolean", "number", "string", "array" or "object" (as nlohmann-json names them).
    [[nodiscard]] const char* type_name() const;
    /// The elements of an array or the members of an object, as written.
    [[nodiscard]] std::size_t size() const;
    /// False for a value its document's Schema did not keep: its kind and size alone (a
    /// container's contents look empty).
    [[nodiscard]] bool kept() const { return !node().skipped(); }
    /// A kept number (precondition: is_number()).
    [[nodiscard]] JsonNumber number() const;
    /// True when this kept value is a number, or a list of them (nested), whose reader found each
    /// one the double its text spells exactly (JsonNumber::Spelling::Exact): the doubles are the
    /// exact values, with nothing to parse.
    [[nodiscard]] bool spells_doubles() const;
    /// A kept string (precondition: is_string()).
    [[nodiscard]] std::string_view string() const;
    /// The value of member `key` of a kept object, if it has one.
    [[nodiscard]] std::optional<Value> find(std::string_view key) const;
    [[nodiscard]] bool contains(std::string_view key) const { return find(key).has_value(); }
    /// The values of members `keys` of a kept object (nullopt for those it lacks), in one pass.
    template <std::size_t N>
    [[nodiscard]] std::array<std::optional<Value>, N> find(const std::array<std::string_view, N>& keys) const;

    /// Calls f(index, element) for each element of a kept array, in order.
    template <class F>
    void for_each_element(F f) const;
    /// Calls f(key, value) for each member of a kept object, in text order.
    template <class F>
    void for_each_member(F f) const;

private:
    [[nodiscard]] const Node& node() const;
    [[nodiscard]] std::size_t after() const;  // the index after this value's nodes

    const Document* doc_;
    std::size_t index_;
};

/// A JSON document as a Schema keeps it (read, read_by_library, document_of): its nodes in
/// blocks (no copies as it grows), texts in the text read or copied into the document.
class Document {
public:
    [[nodiscard]] Value root() const { return Value(*this, 0); }
    /// The nodes it holds, 16 bytes each (what reading keeps beside the text).
    [[nodiscard]] std::size_t nodes() const { return size_; }

private:
    friend class Builder;
    friend class Value;
    static constexpr unsigned kBlockBits = 15;  // 512 KiB blocks
    static constexpr std::size_t kBlock = std::size_t{1} << kBlockBits;

    [[nodiscard]] const Node& node(std::size_t i) const { return blocks_[i >> kBlockBits][i & (kBlock - 1)]; }
    [[nodiscard]] Node& node(std::size_t i) { return blocks_[i >> kBlockBits][i & (kBlock - 1)]; }
    [[nodiscard]] std::string_view text(std::uint32_t at, std::uint32_t length, const Node& n) const {
        return {((n.tag_ & Node::kCopied) != 0 ? copies_.data() : source_.data()) + at, length};
    }

    std::vector<std::unique_ptr<Node[]>> blocks_;
    std::size_t size_ = 0;     // nodes in use
    std::string_view source_;  // the text read
    std::string copies_;       // texts that are not in it
};

/// The document of a JSON text, kept as `schema` says. Malformed JSON is an InputError at "$"
/// (the JSON library's message); a repeated key, or a number that is not 0 but reads as 0.0
/// (1e-400), an InputError at its path. The text must outlive the document.
[[nodiscard]] Document read(std::string_view text, const Schema& schema);
/// The same document read by the JSON library's SAX parser alone (the tests' oracle for read,
/// and the benchmark's alternative).
[[nodiscard]] Document read_by_library(std::string_view text, const Schema& schema);
/// The same by this file's reader alone; nullopt where the text is not plain JSON.
[[nodiscard]] std::optional<Document> read_plain(std::string_view text, const Schema& schema);
/// The end of the run of ASCII digits that starts at `p` (`end` if it runs to the end): the
/// plain reader's scan past the digits of long numbers, eight bytes at a time.
[[nodiscard]] const char* end_of_digits(const char* p, const char* end);
/// A document built in memory (Python's dicts, C++'s nlohmann::json), kept as `schema` says; its
/// integers get their decimal text, its doubles none (JsonNumber). `doc` must outlive the result.
[[nodiscard]] Document document_of(const nlohmann::json& doc, const Schema& schema);

/// The events of a JSON document, in order, to a Document as a Schema keeps it: how the readers
/// above (and the benchmark's simdjson walk) make documents. Texts that do not outlive the
/// document are passed as Transient and copied when kept.
class Builder {
public:
    enum class Text : std::uint8_t { Lasting, Transient };

    /// Texts passed as Lasting must lie in `source` (less than 4 GiB).
    Builder(const Schema& schema, std::string_view source);
    void null();
    void boolean(bool b);
    /// Throws InputError at the number's path when it is not 0 but `value` is (an underflow).
    void number(double value, std::string_view text, Text lifetime,
                JsonNumber::Spelling spelling = JsonNumber::Spelling::Unknown);
    void string(std::string_view s, Text lifetime);
    void start_object();
    /// Throws InputError at the key's path when the object already has it.
    void key(std::string_view k, Text lifetime);
    void end_object();
    void start_array();
    void end_array();
    /// The document, once the root value is complete.
    [[nodiscard]] Document finish();
    /// The JSON path of the value that begins next ("$.contacts[0].mu"), for a reader's message.
    [[nodiscard]] std::string next_path() const;

private:
    // An open container. Its keys so far (for a repeated one) are keys_[keys_from ..), and the
    // copies of its Transient keys copies_[copies_from ..): stacks that shrink as containers close.
    struct Frame {
        bool is_array = false;
        bool skipped = false;            // its contents are not kept
        std::size_t node = kNoNode;      // its node, if it has one (not inside a skipped container)
        const Schema* schema = nullptr;  // what is kept of its contents
        std::size_t count = 0;           // elements or members so far
        std::string_view key;            // the last key (objects)
        const Schema* member = nullptr;  // what is kept of that key's value (nullptr: nothing)
        std::size_t keys_from = 0, copies_from = 0;
        std::unique_ptr<std::unordered_set<std::string_view>> many;  // its keys, once there are many
        bool unread_key_copied = false;  // copies_.back() is the last key's copy, a key whose value is not read
    };
    static constexpr std::size_t kNoNode = std::numeric_limits<std::size_t>::max();
    static constexpr std::size_t kFewKeys = 16;
    static constexpr std::size_t kMaxDepth = 1'000'000;  // 80 MB of frames

    [[nodiscard]] std::string path() const;  // of the value begun last
    [[nodiscard]] std::string path_of(bool next) const;
    Node* begin_value(Kind kind, const Schema*& place);
    Node& push(Kind kind, bool skipped);
    void open(Kind kind);
    // Where a kept text is (in the source, or copied): its offset; sets kCopied in `tag`.
    std::uint32_t keep(std::string_view s, Text lifetime, std::uint32_t& tag);
    void close();

    Document doc_;
    const Schema* root_;
    std::vector<Frame> frames_;         // the open containers, innermost last
    std::vector<std::string_view> keys_;
    std::deque<std::string> copies_;     // a deque: the copies never move
};

/// A JSON path ("$.contacts[2].mu"), written out only for an error: a place is its parent's path
/// and a member's name or an element's index. A path refers to its parent: both must live while
/// it is used (paths are made on the stack as a reader goes down).
class Path {
public:
    explicit Path(std::string_view root) : name_(root) {}
    Path(const Path& parent, std::string_view member) : parent_(&parent), name_(member) {}
    Path(const Path& parent, std::size_t index) : parent_(&parent), index_(index) {}
    [[nodiscard]] std::string str() const;

private:
    const Path* parent_ = nullptr;
    std::string_view name_;  // the root, or a member's name
    std::size_t index_ = std::numeric_limits<std::size_t>::max();
};

// Typed access, each failure an InputError naming the path.

/// Member `name` of `obj` (an error at `path`, the object's, when it has none).
Value field(const Value& obj, const Path& path, std::string_view name);
/// A finite number of magnitude 0 or in [kSmallestMagnitude, kLargestMagnitude].
double number(const Value& v, const Path& path);
/// A number (as above) that must be >= 0; the error says "expected <what> >= 0".
double nonnegative(const Value& v, const Path& path, const char* what);
/// A vector of finite coordinates of magnitude at most kLargestMagnitude, zero or with its
/// largest coordinate at least kSmallestMagnitude (a direction like [1e-300, 1] is fine).
Vec2 vec2(const Value& v, const Path& path);
Vec3 vec3(const Value& v, const Path& path);
std::vector<Vec3> vec3_list(const Value& v, const Path& path);
std::vector<Vec2> vec2_list(const Value& v, const Path& path);
/// The exact value of a number that number() (or a vector reader) accepted: the decimal its
/// text spells (0.1 is 1/10), or the double itself for a number that was never text.
Rational exact_number(const Value& v);
/// The exact coordinates of a vector that vec2() / vec3() accepted.
Rational2 exact_vec2(const Value& v);
Rational3 exact_vec3(const Value& v);
/// A non-zero [x, y] in field `name` of `obj`.
Vec2 nonzero2(const Value& obj, const Path& path, std::string_view name);
/// v, unless it is zero (an InputError at path).
Vec2 nonzero(const Vec2& v, const Path& path);
/// Adds a warning for each member of `obj` not in `known` (when `warnings` is given), in the
/// order of their keys.
void known_fields(const Value& obj, const Path& path, std::initializer_list<std::string_view> known,
                  InputWarnings* warnings);

/// The exact values (0.1 is 1/10) of a kept body object's "mass", "com", "inertia" (0 when it has
/// none) and "radius_of_gyration", already read and checked, beside the doubles the reader took
/// for them (`doubles`' *_double fields); none when every one is a double (Body::exact,
/// AssemblyBody::exact).
[[nodiscard]] std::shared_ptr<const BodyValues> exact_body_values(const Value& b, BodyValues doubles);

/// A polygon's vertices (a list of [x, y], its problems refused: polygon_problem).
[[nodiscard]] std::vector<Vec2> polygon(const Value& v, const Path& path);

/// The exact vertices of a polygon polygon() accepted (0.1 is 1/10).
[[nodiscard]] std::vector<Rational2> exact_polygon(const Value& v);

/// The polygons of a scene's or an assembly's "obstacles": a list of objects with "polygon".
[[nodiscard]] std::vector<std::vector<Vec2>> obstacles(const Value& list, const Path& path, InputWarnings* w);

/// The contact of a kept object's "point", "normal", "mu" (default 0), "mu_kinetic" (default mu)
/// and "name", with its exact values (0.1 is 1/10); its other members are not looked at.
[[nodiscard]] Contact contact_of(const Value& c, const Path& path);

/// What the scene reader keeps, and the scene of such a document (scene_json.cpp; for the
/// benchmark's other readers).
[[nodiscard]] const Schema& scene_schema();
[[nodiscard]] Scene scene_of(const Document& doc, InputWarnings* warnings);

// Value's templates.

template <std::size_t N>
std::array<std::optional<Value>, N> Value::find(const std::array<std::string_view, N>& keys) const {
    std::array<std::optional<Value>, N> out;
    if (!is_object()) return out;
    for_each_member([&](std::string_view key, const Value& v) {
        for (std::size_t k = 0; k < N; ++k) {
            if (key == keys[k]) out[k] = v;
        }
    });
    return out;
}

inline const Node& Value::node() const { return doc_->node(index_); }

inline std::size_t Value::size() const {
    const Node& n = node();
    return n.kind() == Kind::Array || n.kind() == Kind::Object ? n.pair_[1] : 0;
}

inline std::size_t Value::after() const {
    const Node& n = node();
    return (n.kind() == Kind::Array || n.kind() == Kind::Object) && !n.skipped() ? n.pair_[0] : index_ + 1;
}

template <class F>
void Value::for_each_element(F f) const {
    if (!kept()) return;
    std::size_t i = index_ + 1;
    for (std::size_t k = 0, n = size(); k < n; ++k) {
        const Value element(*doc_, i);
        f(k, element);
        i = element.after();
    }
}

template <class F>
void Value::for_each_member(F f) const {
    if (!kept()) return;
    std::size_t i = index_ + 1;
    for (std::size_t k = 0, n = size(); k < n; ++k) {
        const Node& key = doc_->node(i);
        const Value value(*doc_, i + 1);
        f(doc_->text(key.pair_[0], key.pair_[1], key), value);
        i = value.after();
    }
}

}  // namespace momentlab::json_read
