#include "io/particle_group.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace sphjet::particle_group {

namespace {

constexpr std::array<Field, 10> kFields{{{"x", "m", Type::Float64},
                                         {"z", "m", Type::Float64},
                                         {"u", "m/s", Type::Float64},
                                         {"w", "m/s", Type::Float64},
                                         {"rho", "kg/m^3", Type::Float64},
                                         {"p", "Pa", Type::Float64},
                                         {"m", "kg", Type::Float64},
                                         {"id", "1", Type::Int64},
                                         {"kind", "1", Type::Int32},
                                         {"active", "1", Type::Int32}}};

// The element type of a ParticleSet member as stored.
template <class T>
constexpr Type type_of() {
    if constexpr (std::is_same_v<T, double>) return Type::Float64;
    else if constexpr (std::is_same_v<T, std::int64_t>) return Type::Int64;
    else {
        static_assert(std::is_same_v<T, std::int32_t>, "a particle array of another type");
        return Type::Int32;
    }
}

// Calls f(field, array) for row K of kFields and the ParticleSet member it names; the
// member's type must be the row's (checked at compile time).
template <std::size_t K, class F, class V>
void apply(F& f, V& v) {
    static_assert(type_of<typename std::decay_t<V>::value_type>() == kFields[K].type,
                  "kFields and the ParticleSet members differ in type");
    f(kFields[K], v);
}

template <class PS, class F>
void visit(PS& ps, F&& f) {
    apply<0>(f, ps.x);
    apply<1>(f, ps.z);
    apply<2>(f, ps.u);
    apply<3>(f, ps.w);
    apply<4>(f, ps.rho);
    apply<5>(f, ps.p);
    apply<6>(f, ps.m);
    apply<7>(f, ps.id);
    apply<8>(f, ps.kind);
    apply<9>(f, ps.active);
    static_assert(kFields.size() == 10, "each row of kFields is visited");
}

}  // namespace

std::span<const Field> fields() { return kFields; }

const Field* find(std::string_view name) {
    for (const Field& f : kFields)
        if (name == f.name) return &f;
    return nullptr;
}

hid_t h5_type(Type t) {
    return t == Type::Int64 ? H5T_STD_I64LE : t == Type::Int32 ? H5T_STD_I32LE : H5T_IEEE_F64LE;
}

void check_lengths(const ParticleSet& ps, std::string_view who) {
    const std::size_t n = ps.size();
    visit(ps, [&](const Field& f, const auto& v) {
        if (v.size() != n)
            throw std::invalid_argument(
                fmt::format("{}: particle array {} has {} values, x has {}", who, f.name, v.size(), n));
    });
}

void write(hid_t loc, const ParticleSet& ps, h5::Layout layout) {
    visit(ps, [&](const Field& f, const auto& v) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        h5::write_array(loc, f.name, std::span<const T>(v), f.units, layout);
    });
}

void read(hid_t loc, ParticleSet& ps, std::size_t n) {
    visit(ps, [&](const Field& f, auto& v) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        if constexpr (std::is_same_v<T, double>) v = h5::read_doubles(loc, f.name, n);
        else if constexpr (std::is_same_v<T, std::int64_t>) v = h5::read_int64(loc, f.name, n);
        else v = h5::read_int32(loc, f.name, n);
    });
}

}  // namespace sphjet::particle_group
