#include "json_read.hpp"

#include "momentlab/io/printable.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
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
    const auto spelling = (n.tag_ & Node::kExact) != 0     ? JsonNumber::Spelling::Exact
                          : (n.tag_ & Node::kInexact) != 0 ? JsonNumber::Spelling::Inexact
                                                           : JsonNumber::Spelling::Unknown;
    return {n.number_, doc_->text(n.text_, n.tag_ >> Node::kLengthShift, n), spelling};
}

bool Value::spells_doubles() const {
    for (std::size_t i = index_, end = after(); i < end; ++i) {
        const Node& n = doc_->node(i);
        if (n.skipped() || (n.kind() != Kind::Array && (n.tag_ & Node::kExact) == 0)) return false;
    }
    return true;
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

std::string Builder::path() const { return path_of(false); }

std::string Builder::next_path() const { return path_of(true); }

std::string Builder::path_of(bool next) const {
    std::string out = "$";
    for (const Frame& f : frames_) {
        if (f.is_array) {
            const std::size_t index = next && &f == &frames_.back() ? f.count : f.count - 1;
            out.append(1, '[').append(std::to_string(index)).append(1, ']');
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

void Builder::number(double value, std::string_view text, Text lifetime, JsonNumber::Spelling spelling) {
    const Schema* place = nullptr;
    Node* n = begin_value(Kind::Number, place);
    if (value == 0.0 && nonzero_digits(text)) {
        throw InputError(path(), "a number " + std::string(kTooSmallForADouble));
    }
    if (n == nullptr || n->skipped()) return;
    if (text.size() >= (std::size_t{1} << (32 - Node::kLengthShift))) {
        throw InputError(path(), "a number of more than 33 million characters (expected fewer)");
    }
    n->number_ = value;
    n->text_ = keep(text, lifetime, n->tag_);
    if (spelling == JsonNumber::Spelling::Exact) n->tag_ |= Node::kExact;
    if (spelling == JsonNumber::Spelling::Inexact) n->tag_ |= Node::kInexact;
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
            throw InputError(b_.next_path(), "a number beyond the doubles is out of range (expected " + std::string(kMagnitudeRange) + ")");
        }
        malformed_ = true;
        throw InputError("$", "malformed JSON: " + printable(e.what(), Printable::Ascii, 200));
    }
    /// The library found the text malformed (not an error of the values it gave).
    [[nodiscard]] bool malformed() const { return malformed_; }

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
    bool malformed_ = false;
};

}  // namespace

Document read_by_library(std::string_view text, const Schema& schema) {
    Builder b(schema, text);
    LibraryEvents events(b);
    // The library takes a NUL as the text's end (it would read "[1]\0x" as [1]): the text before
    // it is read for the errors it holds, then the NUL is refused as files refuse it (io/files.cpp).
    const std::size_t nul = text.find('\0');
    if (nul == std::string_view::npos) {
        json::sax_parse(text.begin(), text.end(), &events);
        return b.finish();
    }
    try {
        json::sax_parse(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), &events);
    } catch (const InputError&) {
        if (!events.malformed()) throw;  // an error before the NUL (a repeated key, an underflow)
    }
    throw InputError("$", "not a JSON document: a control byte, byte 0x00 at offset " + std::to_string(nul));
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

}  // namespace momentlab::json_read
