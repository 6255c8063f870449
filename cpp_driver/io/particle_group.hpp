// The HDF5 group /particles: the one place that names its arrays, their types, units and
// order. Snapshots (hdf5_output.cpp) and checkpoints (checkpoint.cpp) both write and read it
// through these functions. Internal to io/, like h5_util.hpp.
//
//   x z u w rho p m   float64 [n], attr units m, m, m/s, m/s, kg/m^3, Pa, kg
//   id                int64 [n], units 1 (stable id = initial index)
//   kind active       int32 [n], units 1 (ParticleKind; 1 in the domain, 0 removed)
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "io/h5_util.hpp"
#include "model/particles.hpp"

namespace sphjet::particle_group {

enum class Type { Float64, Int64, Int32 };

struct Field {
    const char* name;
    const char* units;
    Type type;
};

// The arrays of ParticleSet in the order they are written.
[[nodiscard]] std::span<const Field> fields();
// The field of that name, or nullptr (an extra field such as colour).
[[nodiscard]] const Field* find(std::string_view name);
// The stored HDF5 type of a field (H5T_IEEE_F64LE, H5T_STD_I64LE, H5T_STD_I32LE).
[[nodiscard]] hid_t h5_type(Type t);

// Throws std::invalid_argument "<who>: particle array <name> has <k> values, x has <n>" when
// the arrays of ps differ in length.
void check_lengths(const ParticleSet& ps, std::string_view who);

// Writes every array of ps into the group loc, each with its units attribute, in the order
// of fields().
void write(hid_t loc, const ParticleSet& ps, h5::Layout layout = h5::Layout::Contiguous);
// Reads every array (n values each) of the group loc into ps; nb, nbf and wall stay as they
// are. Throws InputError naming the file and the dataset that is missing or of another length.
void read(hid_t loc, ParticleSet& ps, std::size_t n);

}  // namespace sphjet::particle_group
