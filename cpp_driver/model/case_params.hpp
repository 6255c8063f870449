// Every case parameter described once: its key in the case file, the struct member that holds
// it, unit, default, allowed values and a one-line doc. From this one table
//  - the TOML reader knows its keys and their types, checks ranges and choices and stores the
//    plain keys (config/case_build.cpp), and `--set` knows which keys exist;
//  - the case writer echoes them (config/case_writer.cpp);
//  - SimParams is written to and read from HDF5 attributes (io/h5_util.cpp);
//  - the key tables of cases/CASE_FORMAT.md are made (case_format_tables; a test holds the
//    page to them and `sphjet keys --update cases/CASE_FORMAT.md` writes them).
// Adding a plain option: one row in kParams (case_params.cpp) and the member it names; then
// `sphjet keys --update cases/CASE_FORMAT.md`.
#pragma once

#include <array>
#include <climits>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "model/case_spec.hpp"

namespace sphjet {

// The TOML type of a key.
enum class KeyType { Float, Int, Bool, String };

// The allowed values of a number key, as checked by the reader and written in the tables.
struct Range {
    enum class Kind { Any, Positive, NonNegative, Between } kind = Kind::Any;
    double lo = 0, hi = 0;          // Between: lo < v < hi, or <= where closed
    bool lo_open = false, hi_open = false;
};
inline constexpr Range kAny{};
inline constexpr Range kPositive{Range::Kind::Positive};
inline constexpr Range kNonNegative{Range::Kind::NonNegative};
// [lo, hi], (lo, hi], [lo, hi), (lo, hi); hi = kNoLimit: v >= lo (or > lo).
inline constexpr double kNoLimit = 1e308;
constexpr Range between(double lo, double hi, bool lo_open = false, bool hi_open = false) {
    return {Range::Kind::Between, lo, hi, lo_open, hi_open};
}

// One named value of a choice key; enum members store the enumerator's number.
struct Choice {
    std::string_view name;
    std::int64_t value;
};

// Where a key's value lives: one member of one struct (its owner), seen through a number:
// a double for floats, an integer for integers, booleans and enums (their numbers).
struct Member {
    enum class Store { None, Float, Int, Bool, Enum };
    const void* owner = nullptr;  // owner_tag<S>: which struct
    Store store = Store::None;
    double (*get_f)(const void*) = nullptr;
    void (*set_f)(void*, double) = nullptr;
    std::int64_t (*get_i)(const void*) = nullptr;
    void (*set_i)(void*, std::int64_t) = nullptr;
    const void* (*address)(const void*) = nullptr;  // the member in an owner (HDF5 order)
    std::int64_t max_i = 0;  // the largest integer the member takes from a case
    std::size_t size = 0;    // sizeof the member
};

template <class S>
inline constexpr char owner_tag = 0;

namespace detail {
template <class T>
constexpr Member::Store store_of() {
    if constexpr (std::is_same_v<T, double>) return Member::Store::Float;
    else if constexpr (std::is_same_v<T, bool>) return Member::Store::Bool;
    else if constexpr (std::is_enum_v<T>) return Member::Store::Enum;
    else return Member::Store::Int;
}
template <class S, class T>
S owner_of(T S::*);
template <auto M0, auto... Ms>
struct First {
    using Owner = decltype(owner_of(M0));
};
}  // namespace detail

// The Member of S::m, written member<&S::m>(); of a member's member, member<&S::r, &Rect::x>().
template <auto... Ms>
constexpr Member member() {
    using S = typename detail::First<Ms...>::Owner;
    using T = std::remove_cvref_t<decltype((std::declval<S&>() .* ... .* Ms))>;
    Member m;
    m.owner = &owner_tag<S>;
    m.store = detail::store_of<T>();
    m.size = sizeof(T);
    m.address = [](const void* o) -> const void* { return &(*static_cast<const S*>(o) .* ... .* Ms); };
    if constexpr (std::is_same_v<T, double>) {
        m.get_f = [](const void* o) { return (*static_cast<const S*>(o) .* ... .* Ms); };
        m.set_f = [](void* o, double v) { (*static_cast<S*>(o) .* ... .* Ms) = v; };
    } else {
        m.get_i = [](const void* o) { return static_cast<std::int64_t>((*static_cast<const S*>(o) .* ... .* Ms)); };
        m.set_i = [](void* o, std::int64_t v) { (*static_cast<S*>(o) .* ... .* Ms) = static_cast<T>(v); };
        m.max_i = sizeof(T) < sizeof(std::int64_t) ? 1000000000 : INT64_MAX;
    }
    return m;
}

// The choices of an enum, from its EnumNames table (params.hpp).
template <NamedEnum E>
inline constexpr auto kChoicesOf = [] {
    std::array<Choice, EnumNames<E>::list.size()> out{};
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {EnumNames<E>::list[i].first, static_cast<std::int64_t>(EnumNames<E>::list[i].second)};
    return out;
}();

struct Param {
    std::string_view key;    // path in the case file ("fluid.block[].xmin"); "" when derived
    std::string_view attr;   // SimParams member: its HDF5 attribute name; "" when none
    KeyType type = KeyType::Float;
    std::string_view unit;   // "" when none applies (switches, choices, counts without one)
    Member member;           // Store::None: neither read nor echoed generically
    Range range;
    std::span<const Choice> choices;  // string keys and enums: the names
    std::string_view def;      // the default as the tables write it; "": the member's own
    std::string_view allowed;  // what the tables add to range and choices
    std::string_view doc;      // one line: what it is
    std::string_view legacy;   // the legacy case file's line, for the tables
    std::string_view echo;     // the echo's comment when it is not doc ("-": none)
    bool required = false;
    unsigned hand = 0;         // kHandRead, kHandEcho: code of its own reads / echoes it
    bool h5_optional = false;  // absent from files older than it: read as the default
    std::span<const Choice> h5_choices;  // the "<attr>_name" names in HDF5 files when not choices
};
inline constexpr unsigned kHandRead = 1;  // derived or cross-checked: the case builder reads it
inline constexpr unsigned kHandEcho = 2;  // the writer has a line of its own for it

// The whole table, sections in the order of the echo.
[[nodiscard]] std::span<const Param> case_params();
// The row of a key path ("numerics.kernel", "fluid.block[].xmin"), or nullptr.
[[nodiscard]] const Param* find_param(std::string_view key);
// The section of a key path ("fluid.block[]" for "fluid.block[].xmin", "" at the top).
[[nodiscard]] std::string_view section_of(std::string_view key);
// The last component of a key path.
[[nodiscard]] std::string_view leaf_of(std::string_view key);
// The name of a choice value ("unknown" when none has it), and the names as "a | b".
[[nodiscard]] std::string choice_name(std::span<const Choice> choices, std::int64_t v);
[[nodiscard]] std::string choice_list(std::span<const Choice> choices);
// What a range allows, as the tables write it: "> 0", "[0, 1]", ">= 1".
[[nodiscard]] std::string range_text(const Range& g);
// The unit of a SimParams attribute for p (visc_value: alpha or nu by the viscosity model).
[[nodiscard]] std::string_view attr_unit(const Param& row, const SimParams& p);

// The key tables of cases/CASE_FORMAT.md, one per section, each between the lines
// "<!-- keys SECTION -->" and "<!-- end keys -->"; and a page with its tables replaced by
// these (a marker without a section of the table is left as it is).
[[nodiscard]] std::string case_format_table(std::string_view section);
[[nodiscard]] std::string with_case_format_tables(const std::string& page);

}  // namespace sphjet
