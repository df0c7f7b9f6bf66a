#include "view/ResultFileReader.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

namespace mcdda::view {

namespace {

/// Counts and indices of mcdda's files are Int32.
constexpr long long max_count = std::numeric_limits<std::int32_t>::max();

enum class Type { Float64, Int32, UInt8 };

const char* type_name(Type t) { return t == Type::Float64 ? "Float64" : t == Type::Int32 ? "Int32" : "UInt8"; }

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

bool is_name_char(char c, bool first)
{
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
    return first ? letter : letter || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == ':';
}

/// Text of the file for a message: quoted, at most 40 characters, control bytes as '?'.
std::string shown(const std::string& text)
{
    std::string s = text.substr(0, 40);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return "\"" + s + (text.size() > 40 ? "...\"" : "\"");
}

struct Attribute {
    std::string name, value;
    std::size_t pos = 0;
};

struct Tag {
    std::string name;
    std::vector<Attribute> attributes;
    std::size_t pos = 0;  ///< of its '<'
    bool closing = false; ///< </name>
    bool empty = false;   ///< <name ... />

    const Attribute* find(const char* n) const
    {
        for (const Attribute& a : attributes)
            if (a.name == n) return &a;
        return nullptr;
    }
};

/// The root element is not named in messages by its element name (it would read as a VTK
/// library message).
std::string element(const std::string& name) { return name == "VTKFile" ? "the root element" : "<" + name + ">"; }

/// One DataArray as read.
struct Array {
    std::string place;       ///< FieldData, Points, Cells, Verts, Lines, PointData, CellData
    std::string name;        ///< empty: none given (Points)
    std::size_t tag_pos = 0, values_pos = 0;
    std::string type_text, components_text, tuples_text;
    bool has_components = false, has_tuples = false;
    std::size_t components_pos = 0, tuples_pos = 0;
    Type type = Type::Float64;
    int components = 1;
    std::vector<double> reals;    ///< Float64
    std::vector<long long> ints;  ///< Int32, UInt8

    std::size_t size() const { return type == Type::Float64 ? reals.size() : ints.size(); }
    std::string label() const { return "the " + place + " array" + (name.empty() ? "" : " \"" + name + "\""); }
};

/// The number of values an array must hold and why ("3 for each of 1902 points").
struct Need {
    std::size_t count = 0;
    std::string why;
};

/// The component counts mcdda writes for the arrays it names (RunOutput, StrengthReduction);
/// 0 for a name it does not write.
int known_components(const std::string& name)
{
    static const std::pair<const char*, int> table[] = {
        {"displacement", 3}, {"velocity", 3}, {"displacement_increment", 3},
        {"stress", 6}, {"effective_stress", 6},
        {"plastic_state", 1}, {"plastic_strain", 1}, {"plastic_strain_increment", 1}, {"pore_pressure", 1},
        {"present", 1}, {"block", 1}, {"material", 1},
        {"force", 3}, {"normal", 3}, {"normal_force", 1}, {"shear_force", 1}, {"opening", 1}, {"slip", 1},
        {"state", 1}, {"vertex_block", 1}, {"edge_block", 1}, {"joint", 1}, {"water_pressure", 1},
        {"effective_normal_force", 1}, {"bolt_force", 1},
        {"step", 1}, {"stage", 1}, {"time", 1}, {"strength_factor", 1},
    };
    for (const auto& [n, c] : table)
        if (name == n) return c;
    return 0;
}

class Reader {
public:
    Reader(std::string path, const char* kind) : path_(std::move(path)), kind_(kind)
    {
        std::ifstream in(path_, std::ios::binary);
        if (!in) throw ResultFileError("cannot read " + path_ + ": it cannot be opened");
        in.seekg(0, std::ios::end);
        const std::streamoff size = in.tellg();
        in.seekg(0, std::ios::beg);
        if (size < 0) throw ResultFileError("cannot read " + path_ + ": its size is unknown");
        text_.resize(static_cast<std::size_t>(size));
        in.read(text_.data(), size);
        if (in.gcount() != size) throw ResultFileError("cannot read " + path_ + ": reading it failed");
    }

    const std::string& path() const { return path_; }

    [[noreturn]] void fail(std::size_t pos, const std::string& what) const
    {
        throw ResultFileError(path_ + ":" + std::to_string(line_of(pos)) + ": " + what);
    }

    std::size_t line_of(std::size_t pos) const
    {
        pos = std::min(pos, text_.size());
        return 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    }

    /// The XML declaration mcdda writes, exactly, at the very start.
    void prolog()
    {
        static const std::string declaration = "<?xml version=\"1.0\"?>";
        if (text_.empty()) fail(0, "the file is empty: not a " + kind_ + " of mcdda run");
        if (text_.compare(0, declaration.size(), declaration) != 0)
            fail(0, "not a " + kind_ + " of mcdda run (it does not begin with " + declaration + ")");
        at_ = declaration.size();
    }

    /// The root element, of `type`.
    Tag root(const char* type)
    {
        Tag t = next_tag("the file");
        if (t.closing || t.name != "VTKFile")
            fail(t.pos, "not a " + kind_ + " of mcdda run (its first element is <" + std::string(t.closing ? "/" : "") +
                            t.name + ">)");
        allow_only(t, {"type", "version", "byte_order", "header_type"});
        const std::string& holds = required(t, "type").value;
        if (holds != type)
            fail(t.pos, "the file holds " + shown(holds) + " data, not the " + type + " of a " + kind_ + " of mcdda run");
        one_of(t, "version", {"0.1", "1.0", "2.0"}, true);
        one_of(t, "byte_order", {"LittleEndian", "BigEndian"}, false);
        one_of(t, "header_type", {"UInt32", "UInt64"}, false);
        not_empty(t);
        return t;
    }

    /// The next tag, whitespace skipped; anything but a start or end tag is refused.
    Tag next_tag(const std::string& inside)
    {
        skip_space();
        if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + inside + ")");
        Tag t;
        t.pos = at_;
        if (text_[at_] != '<') {
            std::size_t end = at_;
            while (end < text_.size() && !is_space(text_[end]) && text_[end] != '<') ++end;
            fail(at_, "unexpected text " + shown(text_.substr(at_, end - at_)) + " inside " + inside);
        }
        ++at_;
        if (at_ < text_.size() && text_[at_] == '!') {
            if (text_.compare(at_, 8, "!DOCTYPE") == 0)
                fail(t.pos, "a <!DOCTYPE> declaration (entity definitions) is not part of a " + kind_ +
                                " of mcdda run; it is not read");
            if (text_.compare(at_, 3, "!--") == 0) fail(t.pos, "comments are not part of a " + kind_ + " of mcdda run");
            fail(t.pos, "markup <! ... > is not part of a " + kind_ + " of mcdda run");
        }
        if (at_ < text_.size() && text_[at_] == '?')
            fail(t.pos, "a processing instruction <? ... ?> is not part of a " + kind_ + " of mcdda run");
        if (at_ < text_.size() && text_[at_] == '/') t.closing = true, ++at_;
        t.name = name();
        if (t.name.empty()) fail(t.pos, "a damaged tag (no element name after '<')");
        const std::string in_tag = "the tag <" + std::string(t.closing ? "/" : "") + t.name + "> begun on line " +
                                   std::to_string(line_of(t.pos));
        for (;;) {
            const std::size_t before = at_;
            skip_space();
            if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + in_tag + ")");
            if (text_[at_] == '>') {
                ++at_;
                return t;
            }
            if (!t.closing && text_[at_] == '/') {
                if (at_ + 1 < text_.size() && text_[at_ + 1] == '>') {
                    at_ += 2;
                    t.empty = true;
                    return t;
                }
                fail(at_, "a damaged tag <" + t.name + "> ('/' not followed by '>')");
            }
            if (t.closing) fail(at_, "a damaged end tag </" + t.name + ">");
            if (before == at_) fail(at_, "a damaged tag <" + t.name + "> (attributes must be separated by spaces)");
            Attribute a;
            a.pos = at_;
            a.name = name();
            if (a.name.empty())
                fail(at_, "a damaged tag <" + t.name + "> (" + shown(text_.substr(at_, 1)) + " where an attribute begins)");
            skip_space();
            if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + in_tag + ")");
            if (text_[at_] != '=') fail(at_, "a damaged tag <" + t.name + "> (attribute " + a.name + " has no value)");
            ++at_;
            skip_space();
            if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + in_tag + ")");
            const char quote = text_[at_];
            if (quote != '"' && quote != '\'')
                fail(at_, "a damaged tag <" + t.name + "> (the value of " + a.name + " is not quoted)");
            const std::size_t from = ++at_;
            while (at_ < text_.size() && text_[at_] != quote) {
                if (text_[at_] == '&')
                    fail(at_, "the value of " + a.name + " holds an entity or character reference ('&'), which a " + kind_ +
                                  " of mcdda run does not use; it is not expanded");
                if (text_[at_] == '<') fail(at_, "a damaged tag <" + t.name + "> ('<' in the value of " + a.name + ")");
                ++at_;
            }
            if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + in_tag + ")");
            a.value = text_.substr(from, at_ - from);
            ++at_;
            if (t.find(a.name.c_str()) != nullptr)
                fail(a.pos, element(t.name) + " has the attribute " + a.name + " twice");
            t.attributes.push_back(std::move(a));
        }
    }

    /// The start tag of `name` (not self-closing) next, inside `parent`.
    Tag expect_open(const char* name, const Tag& parent)
    {
        Tag t = next_tag(element(parent.name));
        if (t.closing || t.name != name)
            fail(t.pos, "expected <" + std::string(name) + "> inside " + element(parent.name) + ", found <" +
                            (t.closing ? "/" : "") + t.name + ">");
        return t;
    }

    /// The end tag of `open` next.
    void expect_close(const Tag& open)
    {
        Tag t = next_tag(element(open.name) + " begun on line " + std::to_string(line_of(open.pos)));
        if (!t.closing || t.name != open.name)
            fail(t.pos, "expected the end of " + element(open.name) + " begun on line " + std::to_string(line_of(open.pos)) +
                            ", found <" + (t.closing ? "/" : "") + t.name + ">");
    }

    /// Nothing but whitespace after the root element.
    void finish()
    {
        skip_space();
        if (at_ < text_.size()) fail(at_, "text after the end of the root element");
    }

    void allow_only(const Tag& t, std::initializer_list<const char*> names) const
    {
        for (const Attribute& a : t.attributes)
            if (std::none_of(names.begin(), names.end(), [&](const char* n) { return a.name == n; }))
                fail(a.pos, element(t.name) + " has an attribute " + shown(a.name) + ", which a " + kind_ +
                                " of mcdda run does not have");
    }

    void not_empty(const Tag& t) const
    {
        if (t.empty) fail(t.pos, element(t.name) + " is empty (a self-closing tag)");
    }

    const Attribute& required(const Tag& t, const char* name) const
    {
        const Attribute* a = t.find(name);
        if (a == nullptr) fail(t.pos, element(t.name) + " has no " + name);
        return *a;
    }

    void one_of(const Tag& t, const char* name, std::initializer_list<const char*> values, bool needed) const
    {
        const Attribute* a = needed ? &required(t, name) : t.find(name);
        if (a == nullptr) return;
        if (std::none_of(values.begin(), values.end(), [&](const char* v) { return a->value == v; }))
            fail(a->pos, element(t.name) + " has " + name + " " + shown(a->value) + ", which a " + kind_ +
                             " of mcdda run does not have");
    }

    /// A declared count: a whole number, at most max_count when `limit`.
    long long count(const Tag& t, const char* name, bool limit = true) const
    {
        const Attribute& a = required(t, name);
        const std::string& text = a.value;
        if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
            fail(a.pos, std::string(name) + " " + shown(text) + " is not a count");
        const long long n = std::stoll(text);
        if (limit) check_limit(t, name, n);
        return n;
    }

    void check_limit(const Tag& t, const char* name, long long n) const
    {
        if (n > max_count)
            fail(t.find(name)->pos, std::string(name) + " " + std::to_string(n) + " is more than a " + kind_ +
                                        " can hold (" + std::to_string(max_count) + " at most)");
    }

    /// The DataArrays of the section `open` (FieldData, Cells, PointData, ...) up to its end tag;
    /// `prepare` checks an array's name, type and components and says how many values it needs.
    std::vector<Array> read_section(const Tag& open, const std::function<Need(Array&)>& prepare)
    {
        std::vector<Array> arrays;
        if (open.empty) return arrays;
        const std::string inside = element(open.name) + " begun on line " + std::to_string(line_of(open.pos));
        for (;;) {
            Tag t = next_tag(inside);
            if (t.closing) {
                if (t.name != open.name) fail(t.pos, "expected the end of " + inside + ", found </" + t.name + ">");
                return arrays;
            }
            if (t.name != "DataArray")
                fail(t.pos, "unexpected element <" + t.name + "> inside " + element(open.name) + " (only DataArray)");
            Array a = header(t, open.name);
            for (const Array& b : arrays)
                if (b.name == a.name)
                    fail(t.pos, "a second " + open.name + " array named " + shown(a.name) + " (the first is on line " +
                                    std::to_string(line_of(b.tag_pos)) + ")");
            const Need need = prepare(a);
            values(a, need);
            arrays.push_back(std::move(a));
        }
    }

    /// A DataArray's attributes.
    Array header(const Tag& t, const std::string& place) const
    {
        allow_only(t, {"type", "Name", "NumberOfComponents", "NumberOfTuples", "format"});
        Array a;
        a.place = place;
        a.tag_pos = t.pos;
        if (const Attribute* n = t.find("Name")) {
            if (n->value.empty()) fail(n->pos, "a " + place + " array with an empty name");
            for (char c : n->value)
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                    fail(n->pos, "a " + place + " array name " + shown(n->value) + " holds control characters");
            a.name = n->value;
        }
        const Attribute& type = required(t, "type");
        a.type_text = type.value;
        const Attribute& format = required(t, "format");
        if (format.value != "ascii")
            fail(format.pos, a.label() + " is stored as format=" + shown(format.value) + "; a " + kind_ +
                                 " of mcdda run is ASCII (format=\"ascii\")");
        if (const Attribute* c = t.find("NumberOfComponents"))
            a.has_components = true, a.components_text = c->value, a.components_pos = c->pos;
        if (const Attribute* n = t.find("NumberOfTuples"))
            a.has_tuples = true, a.tuples_text = n->value, a.tuples_pos = n->pos;
        if (t.empty) fail(t.pos, a.label() + " has no values (a self-closing tag)");
        return a;
    }

    /// The array's type must be `type`.
    void require_type(Array& a, Type type) const
    {
        if (a.type_text != type_name(type))
            fail(a.tag_pos, a.label() + " has type " + shown(a.type_text) + ", not the " + type_name(type) +
                                " mcdda writes there");
        a.type = type;
    }

    /// The array's NumberOfComponents must be `n` (and may be left out when `optional`).
    void require_components(Array& a, int n, bool optional) const
    {
        if (!a.has_components) {
            if (!optional) fail(a.tag_pos, a.label() + " has no NumberOfComponents (mcdda writes " + std::to_string(n) + ")");
            a.components = n;
            return;
        }
        if (a.components_text != std::to_string(n))
            fail(a.components_pos, a.label() + " has NumberOfComponents " + shown(a.components_text) + ", not the " +
                                       std::to_string(n) + " mcdda writes");
        a.components = n;
    }

    /// A field of point or cell data: the components mcdda writes for its name; 1, 3 or 6 (a
    /// scalar, a vector, a symmetric tensor) for a name it does not know.
    void field_components(Array& a) const
    {
        if (const int known = known_components(a.name); known > 0) return require_components(a, known, false);
        if (!a.has_components) fail(a.tag_pos, a.label() + " has no NumberOfComponents");
        if (a.components_text != "1" && a.components_text != "3" && a.components_text != "6")
            fail(a.components_pos, a.label() + " has NumberOfComponents " + shown(a.components_text) +
                                       ", not 1, 3 or 6 (the counts mcdda writes)");
        a.components = a.components_text[0] - '0';
    }

    /// NumberOfTuples, when given, must be `tuples`.
    void check_tuples(const Array& a, long long tuples) const
    {
        if (a.has_tuples && a.tuples_text != std::to_string(tuples))
            fail(a.tuples_pos, a.label() + " has NumberOfTuples " + shown(a.tuples_text) + ", not " +
                                   std::to_string(tuples));
    }

    /// The position of the k-th value of `a` (for messages).
    std::size_t value_pos(const Array& a, std::size_t k) const
    {
        std::size_t p = a.values_pos;
        for (std::size_t i = 0;; ++i) {
            while (p < text_.size() && is_space(text_[p])) ++p;
            if (i == k || p >= text_.size() || text_[p] == '<') return p;
            while (p < text_.size() && !is_space(text_[p]) && text_[p] != '<') ++p;
        }
    }

    /// The k-th value of `a` as written.
    std::string value_text(const Array& a, std::size_t k) const
    {
        std::size_t p = value_pos(a, k), e = p;
        while (e < text_.size() && !is_space(text_[e]) && text_[e] != '<') ++e;
        return text_.substr(p, e - p);
    }

private:
    std::string path_, kind_;
    std::string text_;
    std::size_t at_ = 0;

    void skip_space()
    {
        while (at_ < text_.size() && is_space(text_[at_])) ++at_;
    }

    std::string name()
    {
        const std::size_t from = at_;
        while (at_ < text_.size() && is_name_char(text_[at_], at_ == from)) ++at_;
        return text_.substr(from, at_ - from);
    }

    /// The values of `a` up to </DataArray>: exactly need.count of them.
    void values(Array& a, const Need& need)
    {
        a.values_pos = at_;
        const std::string inside = a.label() + " begun on line " + std::to_string(line_of(a.tag_pos));
        for (;;) {
            skip_space();
            if (at_ >= text_.size()) fail(at_, "the file is damaged (it ends inside " + inside + ")");
            if (text_[at_] == '<') {
                Tag t = next_tag(inside);
                if (!t.closing || t.name != "DataArray")
                    fail(t.pos, inside + " is not closed before <" + std::string(t.closing ? "/" : "") + t.name + ">");
                break;
            }
            const std::size_t from = at_;
            while (at_ < text_.size() && !is_space(text_[at_]) && text_[at_] != '<') ++at_;
            if (a.size() >= need.count)
                fail(from, a.label() + " holds more than the " + std::to_string(need.count) + " values it should (" +
                               need.why + ")");
            const char* first = text_.data() + from;
            const char* last = text_.data() + at_;
            const std::string token(first, last);
            if (a.type == Type::Float64) {
                double v = 0.0;
                const auto r = std::from_chars(first, last, v);
                if (r.ec != std::errc() || r.ptr != last)
                    fail(from, shown(token) + " in " + a.label() + " is not a number" +
                                   (r.ec == std::errc::result_out_of_range ? " of Float64's range" : ""));
                a.reals.push_back(v);
            } else {
                long long v = 0;
                const auto r = std::from_chars(first, last, v);
                const long long low = a.type == Type::Int32 ? std::numeric_limits<std::int32_t>::min() : 0;
                const long long high = a.type == Type::Int32 ? max_count : 255;
                if (r.ec != std::errc() || r.ptr != last || v < low || v > high)
                    fail(from, shown(token) + " in " + a.label() + " is not a whole number from " +
                                   std::to_string(low) + " to " + std::to_string(high) + " (" + type_name(a.type) + ")");
                a.ints.push_back(v);
            }
        }
        if (a.size() != need.count)
            fail(a.tag_pos, a.label() + " holds " + std::to_string(a.size()) + " values instead of " +
                                std::to_string(need.count) + " (" + need.why + ")");
    }
};

std::string each(std::size_t per, long long count, const char* what)
{
    return std::to_string(per) + " for each of " + std::to_string(count) + " " + what;
}

/// FieldData (step, stage, time, strength_factor): Float64, one component, finite; step and
/// stage whole numbers.
std::vector<Array> read_field_data(Reader& r, const Tag& open)
{
    r.allow_only(open, {});
    std::vector<Array> arrays = r.read_section(open, [&](Array& a) {
        if (a.name.empty()) r.fail(a.tag_pos, "a FieldData array without a Name");
        r.require_type(a, Type::Float64);
        r.require_components(a, 1, false);
        if (!a.has_tuples) r.fail(a.tag_pos, a.label() + " has no NumberOfTuples");
        const std::string& n = a.tuples_text;
        if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos || std::stoll(n) < 1)
            r.fail(a.tuples_pos, a.label() + " has NumberOfTuples " + shown(n) + ", not a count of 1 to 999999999");
        const auto tuples = static_cast<std::size_t>(std::stoll(n));
        return Need{tuples, "NumberOfTuples " + n};
    });
    for (const Array& a : arrays)
        for (std::size_t k = 0; k < a.reals.size(); ++k) {
            const double v = a.reals[k];
            if (!std::isfinite(v))
                r.fail(r.value_pos(a, k), a.label() + " holds " + shown(r.value_text(a, k)) + ", not a finite number");
            if ((a.name == "step" || a.name == "stage") && (v < 0 || v > max_count || v != std::floor(v)))
                r.fail(r.value_pos(a, k), a.label() + " holds " + shown(r.value_text(a, k)) +
                                              ", not a whole number from 0 to " + std::to_string(max_count));
        }
    return arrays;
}

/// Points: Float64, three components, finite.
Array read_points(Reader& r, const Tag& piece, long long points)
{
    const Tag open = r.expect_open("Points", piece);
    r.allow_only(open, {});
    r.not_empty(open);
    std::vector<Array> arrays = r.read_section(open, [&](Array& a) {
        r.require_type(a, Type::Float64);
        r.require_components(a, 3, false);
        r.check_tuples(a, points);
        return Need{3 * static_cast<std::size_t>(points), each(3, points, "points")};
    });
    if (arrays.size() != 1)
        r.fail(open.pos, "<Points> holds " + std::to_string(arrays.size()) + " arrays instead of one");
    const Array& a = arrays.front();
    for (std::size_t k = 0; k < a.reals.size(); ++k)
        if (!std::isfinite(a.reals[k]))
            r.fail(r.value_pos(a, k), "point " + std::to_string(k / 3) + " has a coordinate that is not a finite number (" +
                                          shown(r.value_text(a, k)) + ")");
    return std::move(arrays.front());
}

/// The cells of a section (Cells, Verts, Lines): connectivity and offsets (and types when
/// `with_types`), every cell of `per_cell` points in range; offsets increasing, the last the
/// connectivity's length.
struct CellArrays {
    Array connectivity, offsets, types;
};

CellArrays read_cells(Reader& r, const Tag& open, long long cells, int per_cell, long long points, bool with_types)
{
    r.allow_only(open, {});
    std::vector<Array> arrays = r.read_section(open, [&](Array& a) {
        if (a.name == "connectivity" || a.name == "offsets") {
            r.require_type(a, Type::Int32);
        } else if (with_types && a.name == "types") {
            r.require_type(a, Type::UInt8);
        } else {
            r.fail(a.tag_pos, "<" + open.name + "> holds an array " + (a.name.empty() ? "without a Name" : shown(a.name)) +
                                  "; mcdda writes only connectivity, offsets" + (with_types ? " and types" : "") + " there");
        }
        r.require_components(a, 1, true);
        r.check_tuples(a, a.name == "connectivity" ? cells * per_cell : cells);
        if (a.name == "connectivity")
            return Need{static_cast<std::size_t>(cells) * static_cast<std::size_t>(per_cell),
                        each(static_cast<std::size_t>(per_cell), cells, "cells")};
        return Need{static_cast<std::size_t>(cells), "one for each of " + std::to_string(cells) + " cells"};
    });
    CellArrays c;
    bool have[3] = {false, false, false};
    for (Array& a : arrays) {
        const int k = a.name == "connectivity" ? 0 : a.name == "offsets" ? 1 : 2;
        have[k] = true;
        (k == 0 ? c.connectivity : k == 1 ? c.offsets : c.types) = std::move(a);
    }
    for (int k = 0; k < (with_types ? 3 : 2); ++k)
        if (!have[k])
            r.fail(open.pos, "<" + open.name + "> has no " + (k == 0 ? "connectivity" : k == 1 ? "offsets" : "types") +
                                 " array");
    // Offsets: increasing, the last the connectivity's length, each cell `per_cell` points.
    const std::vector<long long>& offsets = c.offsets.ints;
    for (std::size_t i = 0; i < offsets.size(); ++i)
        if (offsets[i] <= (i == 0 ? 0 : offsets[i - 1]))
            r.fail(r.value_pos(c.offsets, i), i == 0 ? "the first cell offset is " + std::to_string(offsets[i]) +
                                                           ", not a positive number of points"
                                                     : "cell offsets must increase (offset " + std::to_string(offsets[i]) +
                                                           " follows " + std::to_string(offsets[i - 1]) + ")");
    const long long last = offsets.empty() ? 0 : offsets.back();
    if (last != static_cast<long long>(c.connectivity.ints.size()))
        r.fail(offsets.empty() ? c.offsets.tag_pos : r.value_pos(c.offsets, offsets.size() - 1),
               "the last cell offset is " + std::to_string(last) + ", but the connectivity holds " +
                   std::to_string(c.connectivity.ints.size()) + " indices");
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        const long long previous = i == 0 ? 0 : offsets[i - 1];
        if (offsets[i] - previous != per_cell)
            r.fail(r.value_pos(c.offsets, i), "cell " + std::to_string(i) + " has " +
                                                  std::to_string(offsets[i] - previous) + " points instead of " +
                                                  std::to_string(per_cell) + " (offset " + std::to_string(offsets[i]) +
                                                  " follows " + std::to_string(previous) + ")");
    }
    for (std::size_t j = 0; j < c.connectivity.ints.size(); ++j) {
        const long long id = c.connectivity.ints[j];
        if (id < 0 || id >= points)
            r.fail(r.value_pos(c.connectivity, j), "cell " + std::to_string(j / static_cast<std::size_t>(per_cell)) +
                                                       " names point " + std::to_string(id) + ", but the file has " +
                                                       std::to_string(points) + " points (connectivity damaged)");
    }
    return c;
}

/// PointData or CellData of `tuples` entries: Float64 fields of the components mcdda writes
/// (Int32 block and material among a grid's cell data); Scalars, when given, names one of them.
std::vector<Array> read_data(Reader& r, const Tag& piece, const char* place, long long tuples, const char* entities,
                             bool int_ids, std::string* scalars)
{
    const Tag open = r.expect_open(place, piece);
    r.allow_only(open, {"Scalars"});
    std::vector<Array> arrays = r.read_section(open, [&](Array& a) {
        if (a.name.empty()) r.fail(a.tag_pos, std::string("a ") + place + " array without a Name");
        if (int_ids && (a.name == "block" || a.name == "material")) {
            r.require_type(a, Type::Int32);
            r.require_components(a, 1, true);
        } else {
            r.require_type(a, Type::Float64);
            r.field_components(a);
        }
        r.check_tuples(a, tuples);
        return Need{static_cast<std::size_t>(a.components) * static_cast<std::size_t>(tuples),
                    each(static_cast<std::size_t>(a.components), tuples, entities)};
    });
    if (const Attribute* s = open.find("Scalars"))
        if (std::none_of(arrays.begin(), arrays.end(), [&](const Array& a) { return a.name == s->value; }))
            r.fail(s->pos, std::string("<") + place + "> names Scalars=" + shown(s->value) + ", but holds no array of that name");
    if (const Attribute* s = open.find("Scalars")) *scalars = s->value;
    return arrays;
}

vtkSmartPointer<vtkDataArray> make_array(const Array& a)
{
    vtkSmartPointer<vtkDataArray> out;
    if (a.type == Type::Float64) {
        auto d = vtkSmartPointer<vtkDoubleArray>::New();
        d->SetNumberOfComponents(a.components);
        d->SetNumberOfTuples(static_cast<vtkIdType>(a.reals.size() / static_cast<std::size_t>(a.components)));
        std::copy(a.reals.begin(), a.reals.end(), d->GetPointer(0));
        out = d;
    } else {
        auto d = vtkSmartPointer<vtkIntArray>::New();
        d->SetNumberOfComponents(a.components);
        d->SetNumberOfTuples(static_cast<vtkIdType>(a.ints.size() / static_cast<std::size_t>(a.components)));
        for (std::size_t k = 0; k < a.ints.size(); ++k) d->SetValue(static_cast<vtkIdType>(k), static_cast<int>(a.ints[k]));
        out = d;
    }
    if (!a.name.empty()) out->SetName(a.name.c_str());
    return out;
}

vtkSmartPointer<vtkPoints> make_points(const Array& a)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(make_array(a));
    return points;
}

vtkSmartPointer<vtkCellArray> make_cells(const CellArrays& c)
{
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(static_cast<vtkIdType>(c.offsets.ints.size() + 1));
    offsets->SetValue(0, 0);
    for (std::size_t i = 0; i < c.offsets.ints.size(); ++i)
        offsets->SetValue(static_cast<vtkIdType>(i + 1), static_cast<vtkIdType>(c.offsets.ints[i]));
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(c.connectivity.ints.size()));
    for (std::size_t j = 0; j < c.connectivity.ints.size(); ++j)
        connectivity->SetValue(static_cast<vtkIdType>(j), static_cast<vtkIdType>(c.connectivity.ints[j]));
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    return cells;
}

void add_arrays(vtkFieldData* to, const std::vector<Array>& arrays)
{
    for (const Array& a : arrays) to->AddArray(make_array(a));
}

/// Point or cell data with the active scalars their element named (as VTK's readers set them).
void add_arrays(vtkDataSetAttributes* to, const std::vector<Array>& arrays, const std::string& scalars)
{
    for (const Array& a : arrays) to->AddArray(make_array(a));
    if (!scalars.empty()) to->SetActiveScalars(scalars.c_str());
}

/// The opening of a file of data set `type` up to its one <Piece>: the declaration, the
/// <VTKFile> root, the data set element and its optional <FieldData> (read into `field_data`).
struct Opening {
    Tag root, body, piece;
};
Opening open_piece(Reader& r, const char* type, std::vector<Array>& field_data)
{
    r.prolog();
    Opening o;
    o.root = r.root(type);
    o.body = r.expect_open(type, o.root);
    r.allow_only(o.body, {});
    r.not_empty(o.body);
    o.piece = r.next_tag(element(o.body.name));
    if (!o.piece.closing && o.piece.name == "FieldData") {
        field_data = read_field_data(r, o.piece);
        o.piece = r.next_tag(element(o.body.name));
    }
    if (o.piece.closing || o.piece.name != "Piece")
        r.fail(o.piece.pos, "expected <Piece> inside <" + std::string(type) + ">, found <" + std::string(o.piece.closing ? "/" : "") +
                                o.piece.name + ">");
    return o;
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> read_result_grid(const std::string& path, const ExpectedMesh& mesh)
{
    Reader r(path, "result file");
    std::vector<Array> field_data;
    const auto [root, body, piece] = open_piece(r, "UnstructuredGrid", field_data);
    r.allow_only(piece, {"NumberOfPoints", "NumberOfCells"});
    const long long points = r.count(piece, "NumberOfPoints", false), cells = r.count(piece, "NumberOfCells", false);
    // The declared sizes against the model's before anything is read from them.
    if (static_cast<std::size_t>(points) != mesh.nodes || static_cast<std::size_t>(cells) != mesh.triangles)
        throw ResultFileError("results " + path + " declare " + std::to_string(points) + " points and " +
                              std::to_string(cells) + " cells but the model's mesh has " + std::to_string(mesh.nodes) +
                              " nodes and " + std::to_string(mesh.triangles) +
                              " triangles: were they written by a run of this model (with the same --set options)?");
    r.check_limit(piece, "NumberOfPoints", points);
    r.check_limit(piece, "NumberOfCells", cells);
    r.not_empty(piece);

    const Array coordinates = read_points(r, piece, points);
    const Tag cells_tag = r.expect_open("Cells", piece);
    r.not_empty(cells_tag);
    const int per_cell = mesh.quadratic ? 6 : 3;
    const CellArrays cell_arrays = read_cells(r, cells_tag, cells, per_cell, points, true);
    const long long type = mesh.quadratic ? VTK_QUADRATIC_TRIANGLE : VTK_TRIANGLE;
    for (std::size_t i = 0; i < cell_arrays.types.ints.size(); ++i)
        if (cell_arrays.types.ints[i] != type)
            r.fail(r.value_pos(cell_arrays.types, i),
                   "cell " + std::to_string(i) + " is of type " + std::to_string(cell_arrays.types.ints[i]) + ", not the " +
                       (mesh.quadratic ? "six" : "three") + "-node triangle (type " + std::to_string(type) +
                       ") of the model's mesh");
    std::string point_scalars, cell_scalars;
    const std::vector<Array> point_data = read_data(r, piece, "PointData", points, "points", false, &point_scalars);
    const std::vector<Array> cell_data = read_data(r, piece, "CellData", cells, "cells", true, &cell_scalars);
    r.expect_close(piece);
    r.expect_close(body);
    r.expect_close(root);
    r.finish();

    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(make_points(coordinates));
    vtkNew<vtkUnsignedCharArray> types;
    types->SetNumberOfValues(static_cast<vtkIdType>(cells));
    for (vtkIdType i = 0; i < cells; ++i) types->SetValue(i, static_cast<unsigned char>(type));
    grid->SetCells(types, make_cells(cell_arrays));
    add_arrays(grid->GetPointData(), point_data, point_scalars);
    add_arrays(grid->GetCellData(), cell_data, cell_scalars);
    add_arrays(grid->GetFieldData(), field_data);
    return grid;
}

vtkSmartPointer<vtkPolyData> read_contacts_file(const std::string& path)
{
    Reader r(path, "contacts file");
    std::vector<Array> field_data;
    const auto [root, body, piece] = open_piece(r, "PolyData", field_data);
    r.allow_only(piece, {"NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"});
    const long long points = r.count(piece, "NumberOfPoints"), verts = r.count(piece, "NumberOfVerts"),
                    lines = r.count(piece, "NumberOfLines");
    for (const char* none : {"NumberOfStrips", "NumberOfPolys"})
        if (const Attribute* a = piece.find(none); a != nullptr && a->value != "0")
            r.fail(a->pos, std::string(none) + " is " + shown(a->value) + "; a contacts file of mcdda run has none");
    if (verts + lines > max_count)
        r.fail(piece.pos, "NumberOfVerts and NumberOfLines add up to more than a contacts file can hold (" +
                              std::to_string(max_count) + " at most)");
    r.not_empty(piece);

    const Array coordinates = read_points(r, piece, points);
    const Tag verts_tag = r.expect_open("Verts", piece);
    const CellArrays vertex_cells = read_cells(r, verts_tag, verts, 1, points, false);
    const Tag lines_tag = r.expect_open("Lines", piece);
    const CellArrays line_cells = read_cells(r, lines_tag, lines, 2, points, false);
    std::string point_scalars, cell_scalars;
    const std::vector<Array> point_data = read_data(r, piece, "PointData", points, "points", false, &point_scalars);
    const std::vector<Array> cell_data =
        read_data(r, piece, "CellData", verts + lines, "vertices and lines", false, &cell_scalars);
    r.expect_close(piece);
    r.expect_close(body);
    r.expect_close(root);
    r.finish();

    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(make_points(coordinates));
    data->SetVerts(make_cells(vertex_cells));
    data->SetLines(make_cells(line_cells));
    add_arrays(data->GetPointData(), point_data, point_scalars);
    add_arrays(data->GetCellData(), cell_data, cell_scalars);
    add_arrays(data->GetFieldData(), field_data);
    return data;
}

}  // namespace mcdda::view
