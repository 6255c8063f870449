// XDMF 3 index of HDF5 particle snapshots: a temporal collection of Polyvertex grids, so
// that ParaView (Xdmf3ReaderS, or the older "XDMF Reader") opens the whole series with one
// click; an axisymmetric run with revolved copies adds a second collection beside it, which
// ParaView shows as a second block.
//
// Every DataItem points at one whole dataset. ParaView 5.11's XDMF 3 reader loses the points
// when the geometry is assembled from several HDF5 arrays (GeometryType X_Y_Z or X_Y, or a
// JOIN function: zero points, "Skipping unrecognized array type [None]"; X_Y even crashes),
// and it makes no cells for a Polyvertex topology without connectivity. So the snapshot
// carries an n x 3 points dataset and n x 3 vector datasets (HDF5 virtual datasets over the
// 1-D arrays: no extra space) and a connectivity 0..n-1 (compressed).
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace sphjet::xdmf {

enum class NumberType { Float64, Int32, Int64 };

// A point attribute read from one dataset: 1-D [n] for a Scalar, [n x 3] float64 for a Vector.
struct Field {
    std::string name;     // attribute name shown in ParaView
    std::string dataset;  // path inside the grid's HDF5 file, e.g. "/particles/rho"
    NumberType type = NumberType::Float64;
    bool vector = false;
};

struct Grid {
    std::string name;
    std::string h5_file;       // as the index should name it: relative to the .xmf file
    double time = 0.0;         // [s]
    std::size_t n = 0;         // points
    std::string connectivity;  // int64 [n]: 0, 1, ..., n-1
    std::string points;        // float64 [n x 3]
    std::vector<Field> fields;
};

// A temporal collection: one grid per time. ParaView shows each collection of a document as
// a block of its own.
struct Collection {
    std::string name;
    std::vector<Grid> grids;
};

// The XDMF document: one temporal collection per entry, in that order (each written even when
// it has no grid); times are written with 17 significant digits (exact doubles).
[[nodiscard]] std::string document(std::span<const Collection> collections);
// The same with one collection named "particles".
[[nodiscard]] std::string document(std::span<const Grid> grids);

// Writes document(...) to path atomically (path.tmp, fsync, rename: io/file_write.hpp);
// throws WriteError.
void write(const std::filesystem::path& path, std::span<const Collection> collections);
void write(const std::filesystem::path& path, std::span<const Grid> grids);

}  // namespace sphjet::xdmf
