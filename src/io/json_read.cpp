#include "json_read.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace momentlab::json_read {

using nlohmann::json;

// Documents.

const Schema kEverything{{}, &kEverything, std::numeric_limits<std::size_t>::max(), &kEverything};

const char* Value::type_name() const {
    switch (kind()) {
        case Kind::Null: return "null";
        case Kind::False:
        case Kind::True: return "boolean";
        case Kind::Number: return "number";
        case Kind::String: return "string";
        case Kind::Array: return "array";
        case Kind::Object: return "object";
        case Kind::Key: break;
    }
    return "key";
}

JsonNumber Value::number() const {
    const Node& n = node();
    assert(n.kind() == Kind::Number && !n.skipped());
    return {n.number_, doc_->text(n.text_, n.tag_ >> Node::kLengthShift, n)};
}

std::string_view Value::string() const {
    const Node& n = node();
    assert(n.kind() == Kind::String && !n.skipped());
    return doc_->text(n.pair_[0], n.pair_[1], n);
}

std::optional<Value> Value::find(std::string_view key) const {
    if (!is_object() || !kept()) return std::nullopt;
    std::size_t i = index_ + 1;
    for (std::size_t k = 0, n = size(); k < n; ++k) {
        const Node& name = doc_->node(i);
        const Value value(*doc_, i + 1);
        if (doc_->text(name.pair_[0], name.pair_[1], name) == key) return value;
        i = value.after();
    }
    return std::nullopt;
}

Builder::Builder(const Schema& schema, std::string_view source) : root_(&schema) {
    if (source.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw InputError("$", "a JSON text of 4 GiB or more (expected less)");
    }
    doc_.source_ = source;
}

std::string Builder::path() const {
    std::string out = "$";
    for (const Frame& f : frames_) {
        if (f.is_array) {
            out.append(1, '[').append(std::to_string(f.count - 1)).append(1, ']');
        } else {
            out.append(1, '.').append(f.key);
        }
    }
    return out;
}

// The node of a value that begins, or nullptr inside a skipped container; `place` is what is
// kept of it (nullptr: nothing, the node is skipped).
Node* Builder::begin_value(Kind kind, const Schema*& place) {
    place = root_;
    if (!frames_.empty()) {
        Frame& f = frames_.back();
        if (f.is_array) {
            ++f.count;
            if (f.skipped) return nullptr;
            if (f.count > f.schema->max_elements) {  // longer than its place keeps: skipped from here
                doc_.size_ = f.node + 1;
                doc_.node(f.node).tag_ |= Node::kSkipped;
                f.skipped = true;
                return nullptr;
            }
            place = f.schema->elements;
        } else {
            if (f.skipped) return nullptr;
            place = f.member;
        }
    }
    if (kind == Kind::Array && place && place->elements == nullptr) place = nullptr;
    if (kind == Kind::Object && place && place->members.empty() && place->others == nullptr) place = nullptr;
    return &push(kind, place == nullptr);
}

Node& Builder::push(Kind kind, bool skipped) {
    if (doc_.size_ == doc_.blocks_.size() * Document::kBlock) {
        doc_.blocks_.emplace_back(new Node[Document::kBlock]);  // not initialised: Node has no initialisers
    }
    Node& n = doc_.node(doc_.size_++);
    n.number_ = 0.0;
    n.text_ = 0;
    n.tag_ = static_cast<std::uint32_t>(kind) | (skipped ? Node::kSkipped : 0u);
    return n;
}

// A container begins: its node (if any) and its frame.
void Builder::open(Kind kind) {
    const Schema* place = nullptr;
    const Node* n = begin_value(kind, place);
    if (frames_.size() == kMaxDepth) throw InputError("$", "nested more than 1000000 levels deep (expected fewer)");
    frames_.push_back(Frame{kind == Kind::Array, n == nullptr || n->skipped(), n == nullptr ? kNoNode : doc_.size_ - 1,
                            place, 0, {}, nullptr, keys_.size(), copies_.size(), nullptr});
}

std::uint32_t Builder::keep(std::string_view s, Text lifetime, std::uint32_t& tag) {
    if (lifetime == Text::Lasting) {
        assert(s.empty() || (s.data() >= doc_.source_.data() && s.data() + s.size() <= doc_.source_.data() + doc_.source_.size()));
        return s.empty() ? 0 : static_cast<std::uint32_t>(s.data() - doc_.source_.data());
    }
    if (doc_.copies_.size() + s.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw InputError(path(), "more than 4 GiB of strings (expected less)");
    }
    tag |= Node::kCopied;
    const auto at = static_cast<std::uint32_t>(doc_.copies_.size());
    doc_.copies_.append(s);
    return at;
}

void Builder::null() {
    const Schema* place = nullptr;
    begin_value(Kind::Null, place);
}

void Builder::boolean(bool b) {
    const Schema* place = nullptr;
    begin_value(b ? Kind::True : Kind::False, place);
}

void Builder::number(double value, std::string_view text, Text lifetime) {
    const Schema* place = nullptr;
    Node* n = begin_value(Kind::Number, place);
    if (value == 0.0 && nonzero_digits(text)) {
        throw InputError(path(), "a number too small for a double: it would be taken as 0 (expected " +
                                 std::string(kMagnitudeRange) + ")");
    }
    if (n == nullptr || n->skipped()) return;
    if (text.size() >= (std::size_t{1} << (32 - Node::kLengthShift))) {
        throw InputError(path(), "a number of more than 100 million characters (expected fewer)");
    }
    n->number_ = value;
    n->text_ = keep(text, lifetime, n->tag_);
    n->tag_ |= static_cast<std::uint32_t>(text.size()) << Node::kLengthShift;
}

void Builder::string(std::string_view s, Text lifetime) {
    const Schema* place = nullptr;
    Node* n = begin_value(Kind::String, place);
    if (n == nullptr || n->skipped()) return;
    n->pair_[0] = keep(s, lifetime, n->tag_);
    n->pair_[1] = static_cast<std::uint32_t>(s.size());
}

void Builder::start_object() { open(Kind::Object); }

void Builder::start_array() { open(Kind::Array); }

void Builder::key(std::string_view k, Text lifetime) {
    Frame& f = frames_.back();
    ++f.count;
    f.member = nullptr;
    if (!f.skipped) {
        Node& n = push(Kind::Key, false);
        n.pair_[0] = keep(k, lifetime, n.tag_);
        n.pair_[1] = static_cast<std::uint32_t>(k.size());
        f.member = f.schema->others;
        for (const Schema::Member& m : f.schema->members) {
            if (m.key == k) f.member = m.schema;
        }
    }
    if (lifetime == Text::Transient) {  // the document's copy may move; an unread key's copy lives until the next key
        if (f.unread_key_copied) {
            copies_.back() = k;
        } else {
            copies_.emplace_back(k);
        }
        k = copies_.back();
        f.unread_key_copied = f.member == nullptr;
    }
    f.key = k;
    // Repeats are looked for where a key's value is read: in an object the reader skips, or
    // among a kept object's unknown fields, they change nothing, and their keys would cost
    // memory that follows the text rather than the scene.
    if (f.member == nullptr) return;
    bool repeated = false;
    if (f.many == nullptr) {
        repeated = std::find(keys_.begin() + static_cast<std::ptrdiff_t>(f.keys_from), keys_.end(), k) != keys_.end();
        keys_.push_back(k);
        if (keys_.size() - f.keys_from > kFewKeys) {  // many keys: a set of them
            f.many = std::make_unique<std::unordered_set<std::string_view>>(keys_.begin() + static_cast<std::ptrdiff_t>(f.keys_from),
                                                                            keys_.end());
            keys_.resize(f.keys_from);
        }
    } else {
        repeated = !f.many->insert(k).second;
    }
    // JSON parsers differ on which of two equal keys wins: a file with two "mu" fields would
    // mean different scenes to different programs.
    if (repeated) throw InputError(path(), "duplicate key (each key may appear once in an object)");
}

void Builder::close() {
    Frame& f = frames_.back();
    if (f.node != kNoNode) {
        Node& n = doc_.node(f.node);
        if (!n.skipped()) n.pair_[0] = static_cast<std::uint32_t>(doc_.size_);
        n.pair_[1] = static_cast<std::uint32_t>(f.count);
    }
    keys_.resize(f.keys_from);
    copies_.resize(f.copies_from);
    frames_.pop_back();
}

void Builder::end_object() { close(); }

void Builder::end_array() { close(); }

Document Builder::finish() {
    assert(frames_.empty() && doc_.size_ > 0);
    return std::move(doc_);
}

namespace {

// The JSON library's SAX events, to a Builder (its texts do not outlive the event).
class LibraryEvents {
public:
    explicit LibraryEvents(Builder& b) : b_(b) {}
    bool null() { return b_.null(), true; }
    bool boolean(bool v) { return b_.boolean(v), true; }
    bool number_integer(json::number_integer_t v) { return integer(v); }
    bool number_unsigned(json::number_unsigned_t v) { return integer(v); }
    bool number_float(json::number_float_t v, const json::string_t& text) {
        return b_.number(v, text, Builder::Text::Transient), true;
    }
    bool string(json::string_t& s) { return b_.string(s, Builder::Text::Transient), true; }
    bool binary(json::binary_t&) { return b_.null(), true; }  // not in JSON text
    bool start_object(std::size_t) { return b_.start_object(), true; }
    bool key(json::string_t& k) { return b_.key(k, Builder::Text::Transient), true; }
    bool end_object() { return b_.end_object(), true; }
    bool start_array(std::size_t) { return b_.start_array(), true; }
    bool end_array() { return b_.end_array(), true; }
    template <class Exception>
    bool parse_error(std::size_t, const std::string&, const Exception& e) {
        if constexpr (std::is_same_v<Exception, nlohmann::detail::out_of_range>) {  // e.g. 1e999
            throw InputError("$", "a number is out of range (expected " + std::string(kMagnitudeRange) + "): " + e.what());
        }
        throw InputError("$", std::string("malformed JSON: ") + e.what());
    }

private:
    template <class Integer>
    bool integer(Integer v) {
        char text[24];
        const auto end = std::to_chars(text, text + sizeof text, v).ptr;
        b_.number(static_cast<double>(v), std::string_view(text, static_cast<std::size_t>(end - text)),
                  Builder::Text::Transient);
        return true;
    }

    Builder& b_;
};

// A reader of the plain JSON that programs write: ASCII strings without escapes and numbers
// that convert to finite doubles. It reads such a text in one pass over its characters with no
// copies (the library reads a character at a time through its input adapter and copies each
// token: bench/bench_io.cpp), and gives up on anything else, which the library then reads.
class PlainReader {
public:
    PlainReader(std::string_view text, Builder& b) : p_(text.data()), end_(text.data() + text.size()), b_(b) {}

    // Reads the text to the builder; false when the text is not plain JSON.
    bool document() {
        std::vector<bool> arrays;  // the open containers, innermost last: true for an array
        for (;;) {
            skip_space();
            if (p_ == end_) return false;
            if (*p_ == '{' || *p_ == '[') {
                const bool array = *p_++ == '[';
                array ? b_.start_array() : b_.start_object();
                if (next_is(array ? ']' : '}')) {
                    array ? b_.end_array() : b_.end_object();
                } else {
                    arrays.push_back(array);
                    if (!array && !member_key()) return false;
                    continue;  // its first value
                }
            } else if (!scalar()) {
                return false;
            }
            // After a value: a comma and the next value, or the ends of containers.
            for (;;) {
                skip_space();
                if (arrays.empty()) return p_ == end_;
                if (p_ == end_) return false;
                const bool array = arrays.back();
                if (*p_ == ',') {
                    ++p_;
                    if (!array && !member_key()) return false;
                    break;
                }
                if (*p_++ != (array ? ']' : '}')) return false;
                arrays.pop_back();
                array ? b_.end_array() : b_.end_object();
            }
        }
    }

private:
    static bool digit(char c) { return c >= '0' && c <= '9'; }

    void skip_space() {
        while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
    }

    // Whether the text continues with c (after white space); consumes it if so.
    bool next_is(char c) {
        skip_space();
        if (p_ == end_ || *p_ != c) return false;
        ++p_;
        return true;
    }

    // A member's key, then its colon (the key is an event before the colon is read, as the
    // library has it, so that both report a repeated key at the same place).
    bool member_key() {
        skip_space();
        std::string_view key;
        if (p_ == end_ || *p_ != '"' || !string(key)) return false;
        b_.key(key, Builder::Text::Lasting);
        return next_is(':');
    }

    bool scalar() {
        switch (*p_) {
            case '"': {
                std::string_view s;
                if (!string(s)) return false;
                b_.string(s, Builder::Text::Lasting);
                return true;
            }
            case 't': return literal("true") && (b_.boolean(true), true);
            case 'f': return literal("false") && (b_.boolean(false), true);
            case 'n': return literal("null") && (b_.null(), true);
            default: return number();
        }
    }

    // ASCII from the space to DEL between quotes, with no escape.
    bool string(std::string_view& out) {
        const char* start = ++p_;
        for (; p_ != end_; ++p_) {
            const auto c = static_cast<unsigned char>(*p_);
            if (c == '"') {
                out = std::string_view(start, static_cast<std::size_t>(p_++ - start));
                return true;
            }
            if (c < 0x20 || c == '\\' || c >= 0x80) return false;
        }
        return false;
    }

    bool literal(std::string_view word) {
        if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word) return false;
        p_ += word.size();
        return true;
    }

    // JSON's number grammar, and its value as the library gives it: an integer's (+0 for "-0"),
    // or the nearest double.
    bool number() {
        const char* const start = p_;
        const char* q = p_;
        const bool negative = *q == '-';
        if (negative) ++q;
        if (q == end_ || !digit(*q)) return false;
        if (*q == '0') {
            ++q;
        } else {
            while (q != end_ && digit(*q)) ++q;
        }
        const char* const integer_end = q;
        if (q != end_ && *q == '.') {
            const char* const digits = ++q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
        }
        if (q != end_ && (*q == 'e' || *q == 'E')) {
            ++q;
            if (q != end_ && (*q == '+' || *q == '-')) ++q;
            const char* const digits = q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
        }
        p_ = q;
        const std::string_view text(start, static_cast<std::size_t>(q - start));
        double x = 0.0;
        if (q == integer_end && integer_end - start <= 19) {  // up to 18 digits: exact in 64 bits
            std::uint64_t v = 0;
            for (const char* d = start + (negative ? 1 : 0); d != integer_end; ++d) v = v * 10 + static_cast<std::uint64_t>(*d - '0');
            x = negative ? static_cast<double>(-static_cast<std::int64_t>(v)) : static_cast<double>(v);
        } else {
#if defined(__cpp_lib_to_chars)
            const auto [end, error] = std::from_chars(start, q, x);
            if (error != std::errc() || end != q || !std::isfinite(x)) return false;
#else
            return false;  // no exact conversion without a locale: the library reads the text
#endif
        }
        b_.number(x, text, Builder::Text::Lasting);
        return true;
    }

    const char* p_;
    const char* end_;
    Builder& b_;
};

}  // namespace

std::optional<Document> read_plain(std::string_view text, const Schema& schema) {
    Builder b(schema, text);
    if (!PlainReader(text, b).document()) return std::nullopt;
    return b.finish();
}

Document read_by_library(std::string_view text, const Schema& schema) {
    Builder b(schema, text);
    LibraryEvents events(b);
    json::sax_parse(text.begin(), text.end(), &events);
    return b.finish();
}

Document read(std::string_view text, const Schema& schema) {
    // An error the plain reader's builder raises (a repeated key, an underflow) is the one the
    // library would raise: both give the same events in the same order up to it.
    if (std::optional<Document> doc = read_plain(text, schema)) return std::move(*doc);
    return read_by_library(text, schema);
}

Document document_of(const json& doc, const Schema& schema) {
    Builder b(schema, {});
    // Each open container and the next of its items; iterative, as deep as the document is.
    struct Open {
        const json* container;
        json::const_iterator next;
    };
    std::vector<Open> open;
    const auto begin = [&](const json& v) {
        switch (v.type()) {
            case json::value_t::object: b.start_object(); open.push_back({&v, v.begin()}); return;
            case json::value_t::array: b.start_array(); open.push_back({&v, v.begin()}); return;
            case json::value_t::number_integer:
            case json::value_t::number_unsigned: {
                char text[24];
                const auto end = v.is_number_unsigned() ? std::to_chars(text, text + sizeof text, v.get<std::uint64_t>()).ptr
                                                        : std::to_chars(text, text + sizeof text, v.get<std::int64_t>()).ptr;
                b.number(v.get<double>(), std::string_view(text, static_cast<std::size_t>(end - text)), Builder::Text::Transient);
                return;
            }
            case json::value_t::number_float: b.number(v.get<double>(), {}, Builder::Text::Lasting); return;
            case json::value_t::string: b.string(v.get_ref<const std::string&>(), Builder::Text::Transient); return;
            case json::value_t::boolean: b.boolean(v.get<bool>()); return;
            default: b.null(); return;
        }
    };
    begin(doc);
    while (!open.empty()) {
        Open& top = open.back();
        if (top.next == top.container->end()) {
            top.container->is_object() ? b.end_object() : b.end_array();
            open.pop_back();
            continue;
        }
        const auto item = top.next++;
        if (top.container->is_object()) b.key(item.key(), Builder::Text::Transient);
        begin(*item);  // may grow `open`: top is not used after this
    }
    return b.finish();
}

std::optional<Decimal> exact_decimal(std::string_view text) {
    std::size_t i = 0;
    Decimal d;
    d.negative = i < text.size() && text[i] == '-';
    if (d.negative) ++i;
    const auto digits_from = [&](std::size_t from) {
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        return text.substr(from, i - from);
    };
    const std::string_view whole = digits_from(i);
    if (whole.empty() || (whole.size() > 1 && whole[0] == '0')) return std::nullopt;
    std::string_view fraction;
    if (i < text.size() && text[i] == '.') {
        fraction = digits_from(++i);
        if (fraction.empty()) return std::nullopt;
    }
    std::int64_t exponent = 0;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        const bool down = i < text.size() && text[i] == '-';
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        std::string_view e = digits_from(i);
        if (e.empty()) return std::nullopt;
        e.remove_prefix(std::min(e.find_first_not_of('0'), e.size()));
        if (e.size() > 18) return std::nullopt;
        for (const char c : e) exponent = exponent * 10 + (c - '0');
        if (down) exponent = -exponent;
    }
    if (i != text.size()) return std::nullopt;
    // digits x 10^(exponent - |fraction|), then without leading and trailing zeros.
    d.digits.reserve(whole.size() + fraction.size());
    d.digits.append(whole).append(fraction);
    d.exponent = exponent - static_cast<std::int64_t>(fraction.size());
    d.digits.erase(0, std::min(d.digits.find_first_not_of('0'), d.digits.size()));
    const std::size_t last = d.digits.find_last_not_of('0');
    if (last == std::string::npos) return Decimal{};
    d.exponent += static_cast<std::int64_t>(d.digits.size() - 1 - last);
    d.digits.resize(last + 1);
    return d;
}

// Typed access.

std::string Path::str() const {
    std::string out = parent_ ? parent_->str() : std::string();
    if (parent_ == nullptr) return out.append(name_);
    if (index_ != std::numeric_limits<std::size_t>::max()) return out.append(1, '[').append(std::to_string(index_)).append(1, ']');
    return out.append(1, '.').append(name_);
}

Value field(const Value& obj, const Path& path, std::string_view name) {
    const std::optional<Value> v = obj.find(name);
    if (!v) throw InputError(path.str(), "missing field \"" + std::string(name) + "\"");
    return *v;
}

namespace {

// A number's value as the JSON library writes it (in messages).
std::string dumped(double x) { return json(x).dump(); }

// A finite number of magnitude at most kLargestMagnitude.
double coordinate(const Value& v, const Path& path) {
    if (!v.is_number()) throw InputError(path.str(), "expected a number, got " + std::string(v.type_name()));
    const double x = v.number().value;
    if (!std::isfinite(x)) throw InputError(path.str(), "expected a finite number");
    if (!(std::abs(x) <= kLargestMagnitude)) {
        throw InputError(path.str(), "the magnitude of " + dumped(x) + " is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return x;
}

// A vector is 0 or has its largest coordinate in range; single coordinates may be tiny.
template <class V>
V checked(const V& v, const Path& path) {
    if (!magnitude_in_range(v.cwiseAbs().maxCoeff())) {
        throw InputError(path.str(), "the vector's magnitude is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return v;
}

// The coordinates of an array of N numbers, the first bad one an error (in order).
template <int N>
std::array<double, N> coordinates(const Value& v, const Path& path) {
    std::array<double, N> out{};
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = coordinate(c, Path(path, k)); });
    return out;
}

}  // namespace

double number(const Value& v, const Path& path) {
    const double x = coordinate(v, path);
    if (!magnitude_in_range(std::abs(x))) {
        throw InputError(path.str(), "the magnitude of " + dumped(x) + " is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return x;
}

double nonnegative(const Value& v, const Path& path, const char* what) {
    const double x = number(v, path);
    if (x < 0.0) throw InputError(path.str(), std::string("expected ") + what + " >= 0");
    return x;
}

Vec2 vec2(const Value& v, const Path& path) {
    if (!v.is_array() || v.size() != 2) throw InputError(path.str(), "expected [x, y]");
    const auto xy = coordinates<2>(v, path);
    return checked(Vec2(xy[0], xy[1]), path);
}

Vec3 vec3(const Value& v, const Path& path) {
    if (!v.is_array() || v.size() != 3) throw InputError(path.str(), "expected [a, b, c]");
    const auto abc = coordinates<3>(v, path);
    return checked(Vec3(abc[0], abc[1], abc[2]), path);
}

std::vector<Vec3> vec3_list(const Value& v, const Path& path) {
    if (!v.is_array()) throw InputError(path.str(), "expected a list of [a, b, c]");
    std::vector<Vec3> out;
    out.reserve(v.size());
    v.for_each_element([&](std::size_t i, const Value& e) { out.push_back(vec3(e, Path(path, i))); });
    return out;
}

std::vector<Vec2> vec2_list(const Value& v, const Path& path) {
    if (!v.is_array()) throw InputError(path.str(), "expected a list of [x, y]");
    std::vector<Vec2> out;
    out.reserve(v.size());
    v.for_each_element([&](std::size_t i, const Value& e) { out.push_back(vec2(e, Path(path, i))); });
    return out;
}

Rational exact_number(const Value& v) {
    const JsonNumber n = v.number();
    // An integer of at most 15 digits is its double (no need to parse it again).
    const std::string_view t = n.text.substr(!n.text.empty() && n.text[0] == '-' ? 1 : 0);
    if (t.size() <= 15 && t.find_first_not_of("0123456789") == std::string_view::npos) return Rational(n.value);
    const std::optional<Rational> r = Rational::parse(n.text);
    return r ? *r : Rational(n.value);
}

Rational2 exact_vec2(const Value& v) {
    Rational2 out;
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = exact_number(c); });
    return out;
}

Rational3 exact_vec3(const Value& v) {
    Rational3 out;
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = exact_number(c); });
    return out;
}

Vec2 nonzero2(const Value& obj, const Path& path, std::string_view name) {
    const Path p(path, name);
    return nonzero(vec2(field(obj, path, name), p), p);
}

Vec2 nonzero(const Vec2& v, const Path& path) {
    if (v.x() == 0.0 && v.y() == 0.0) throw InputError(path.str(), "expected a non-zero vector");
    return v;
}

namespace {
constexpr std::size_t kListedUnknown = 20;
constexpr const char* kMoreUnknown = "$: ";
}  // namespace

void known_fields(const Value& obj, const Path& path, std::initializer_list<std::string_view> known,
                  InputWarnings* warnings) {
    if (warnings == nullptr || !obj.is_object()) return;
    const auto is_known = [&](std::string_view key) { return std::find(known.begin(), known.end(), key) != known.end(); };
    // The first kListedUnknown unknown fields of a document are listed, one a line, in the order
    // of their names; the rest are counted in one last line (a file of millions of unknown
    // fields gives a few lines, and only the names listed are held).
    const std::size_t room = kListedUnknown - std::min(warnings->size(), kListedUnknown);
    std::vector<std::string_view> first;  // the smallest `room` unknown names, among others
    std::size_t unknown = 0;
    obj.for_each_member([&](std::string_view key, const Value&) {
        if (is_known(key)) return;
        ++unknown;
        first.push_back(key);
        if (first.size() > 2 * room + 64) {
            std::nth_element(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(room), first.end());
            first.resize(room);
        }
    });
    if (unknown == 0) return;
    std::sort(first.begin(), first.end());
    first.resize(std::min(first.size(), room));
    std::string expected;
    for (const std::string_view k : known) expected.append(expected.empty() ? "" : ", ").append(k);
    const std::string at = path.str();
    for (const std::string_view key : first) {
        warnings->push_back(at + "." + std::string(key) + ": unknown field, ignored (expected " + expected + ")");
    }
    std::size_t more = unknown - first.size();
    if (more == 0) return;
    if (warnings->size() > kListedUnknown) {
        more += std::stoull(warnings->back().substr(std::strlen(kMoreUnknown)));
        warnings->pop_back();
    }
    warnings->push_back(kMoreUnknown + std::to_string(more) + " more unknown fields, ignored (the first " +
                        std::to_string(kListedUnknown) + " are listed)");
}

}  // namespace momentlab::json_read

namespace momentlab {

namespace {

// Calls f(token) for each number of a JSON text, in order: the tokens outside strings that
// start with '-' or a digit.
template <class F>
void for_each_number(std::string_view text, F f) {
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t end = i + 1;
            const auto in_number = [](char d) {
                return (d >= '0' && d <= '9') || d == '+' || d == '-' || d == '.' || d == 'e' || d == 'E';
            };
            while (end < text.size() && in_number(text[end])) ++end;
            f(text.substr(i, end - i));
            i = end - 1;
        }
    }
}

}  // namespace

std::optional<std::string> underflowing_number(std::string_view json_text) {
    std::optional<std::string> first;
    for_each_number(json_text, [&](std::string_view token) {
        if (first || !nonzero_digits(token)) return;
        if (std::strtod(std::string(token).c_str(), nullptr) == 0.0) first = std::string(token);
    });
    return first;
}

bool nonzero_digits(std::string_view number) {
    std::size_t i = 0;
    if (i < number.size() && (number[i] == '-' || number[i] == '+')) ++i;
    const bool hex = number.size() >= i + 2 && number[i] == '0' && (number[i + 1] == 'x' || number[i + 1] == 'X');
    if (hex) i += 2;
    for (; i < number.size(); ++i) {
        const char c = number[i];
        if (hex ? (c == 'p' || c == 'P') : (c == 'e' || c == 'E')) break;
        if (c >= '1' && c <= '9') return true;
        if (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))) return true;
    }
    return false;
}

}  // namespace momentlab
