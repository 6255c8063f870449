// Thin RAII layer over the HDF5 C API, shared by the snapshot writer and the checkpoint.
// Internal to io/: the public headers (hdf5_output.hpp, checkpoint.hpp) do not include it.
//
// Every failure throws InputError naming the file and the object ("run/snap_000003.h5:
// /particles/rho: ..."), with HDF5's own innermost message as what was found. HDF5's
// automatic printing of its error stack is switched off while these functions run.
#pragma once

#include <hdf5.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/params.hpp"

namespace sphjet::h5 {

// Owns one HDF5 identifier and closes it with the matching H5*close.
template <herr_t (*Close)(hid_t)>
class Handle {
public:
    Handle() = default;
    explicit Handle(hid_t id) : id_(id) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, H5I_INVALID_HID);
        }
        return *this;
    }
    ~Handle() { reset(); }
    void reset() {
        if (id_ >= 0) Close(id_);
        id_ = H5I_INVALID_HID;
    }
    [[nodiscard]] hid_t get() const { return id_; }
    [[nodiscard]] hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }
    operator hid_t() const { return id_; }  // NOLINT: lets a handle go straight into H5 calls

private:
    hid_t id_ = H5I_INVALID_HID;
};

using File = Handle<H5Fclose>;
using Group = Handle<H5Gclose>;
using Dataset = Handle<H5Dclose>;
using Dataspace = Handle<H5Sclose>;
using Attribute = Handle<H5Aclose>;
using Datatype = Handle<H5Tclose>;
using PropList = Handle<H5Pclose>;

// Switches HDF5's automatic error printing off for its lifetime (restores it after).
class QuietErrors {
public:
    QuietErrors();
    ~QuietErrors();
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

// The innermost message on HDF5's current error stack ("" when empty).
[[nodiscard]] std::string last_error();

// "file: /group/name" for messages.
[[nodiscard]] std::string where(hid_t loc, const std::string& name = {});

// Files. A file is created in memory (HDF5's core driver, no backing store) and reaches the
// disk only through write_file, in one piece via io/file_write.hpp: HDF5 never meets a full
// disk (HDF5 1.10 crashes at exit after a failed H5Fclose), and a failed write leaves no
// temporary file. path is the file's final name (error messages name it); size_hint, the
// bytes of raw data about to be written, sizes the memory buffer. The buffer is kept per
// thread for the next file (as large as the largest file written: a fresh one costs more in
// page faults than the disk write); a second file open at the same time gets its own. Objects are written in the
// HDF5 1.8 format (checksummed metadata, readable by HDF5 1.8 and later) except the virtual
// datasets of write_vec3_view, which need 1.10.
[[nodiscard]] File create_file(const std::filesystem::path& path, std::size_t size_hint = 0);
[[nodiscard]] File open_file(const std::filesystem::path& path);  // read-only
// Finishes a file made by create_file, closes it and writes it to its path atomically
// (write_file_atomically: path.tmp, fsync, rename, fsync of the directory). what names the
// file in messages ("the snapshot"). Throws WriteError (or InputError for an HDF5 failure);
// the previous file at path is then untouched.
void write_file(File& f, const std::filesystem::path& path, std::string_view what);

[[nodiscard]] Group create_group(hid_t loc, const std::string& name);
[[nodiscard]] Group open_group(hid_t loc, const std::string& name);
[[nodiscard]] bool has_link(hid_t loc, const std::string& name);
[[nodiscard]] bool has_attr(hid_t loc, const std::string& name);
[[nodiscard]] std::vector<std::string> link_names(hid_t loc);  // in creation/name order

// Storage of one 1-D array. Contiguous is what ParaView and every tool reads fastest;
// checksummed stores it in chunks with HDF5's Fletcher-32 filter so that a corrupted byte in
// the raw data fails the read instead of coming back as a wrong number.
enum class Layout { Contiguous, Checksummed };

// 1-D datasets of double, int32 or int64 (stored little-endian IEEE / two's complement, so
// values round-trip bit for bit). units: a "units" string attribute when not null.
void write_array(hid_t loc, const std::string& name, std::span<const double> v,
                 const char* units = nullptr, Layout layout = Layout::Contiguous);
void write_array(hid_t loc, const std::string& name, std::span<const std::int32_t> v,
                 const char* units = nullptr, Layout layout = Layout::Contiguous);
void write_array(hid_t loc, const std::string& name, std::span<const std::int64_t> v,
                 const char* units = nullptr, Layout layout = Layout::Contiguous);

// An n x 3 float64 dataset that takes no space in the file: an HDF5 virtual dataset whose
// column k reads the 1-D dataset sources[k] of the same file (absolute path), or 0 where
// sources[k] is empty. The XDMF index uses these for the points (x, 0, z) and for vectors
// such as (u, 0, w), which ParaView's XDMF 3 reader cannot assemble from separate arrays.
// Readers need HDF5 1.10 or later (ParaView 5.x, h5py, h5dump 1.10).
void write_vec3_view(hid_t loc, const std::string& name, const std::array<std::string, 3>& sources,
                     std::size_t n);

// An n x 3 float64 dataset (contiguous) from xyz = x0 y0 z0 x1 y1 z1 ... (3n values).
void write_vec3_array(hid_t loc, const std::string& name, std::span<const double> xyz,
                      const char* units = nullptr);

// A 1-D dataset of copies x n values that takes no space in the file: an HDF5 virtual
// dataset whose values k n .. k n + n - 1 read the 1-D dataset source (absolute path, same
// file, n values) for every k. type is the stored type (H5T_IEEE_F64LE, H5T_STD_I32LE, ...),
// that of source. The revolved copies of an axisymmetric snapshot repeat the ring fields
// this way. One mapping per copy: readers need HDF5 1.10, as for write_vec3_view.
void write_repeat_view(hid_t loc, const std::string& name, const std::string& source, hid_t type,
                       std::size_t n, std::size_t copies);

// 0, 1, ..., n-1 as int64, compressed (a few bytes in the file): the Polyvertex connectivity.
void write_iota(hid_t loc, const std::string& name, std::size_t n);

// Reads a 1-D dataset; InputError when it is missing, not 1-D, of the wrong class, or (when
// expected_size is given) of another length.
[[nodiscard]] std::vector<double> read_doubles(hid_t loc, const std::string& name,
                                               std::optional<std::size_t> expected_size = {});
[[nodiscard]] std::vector<std::int32_t> read_int32(hid_t loc, const std::string& name,
                                                   std::optional<std::size_t> expected_size = {});
[[nodiscard]] std::vector<std::int64_t> read_int64(hid_t loc, const std::string& name,
                                                   std::optional<std::size_t> expected_size = {});

// Scalar attributes.
void write_attr(hid_t loc, const std::string& name, double v);
void write_attr(hid_t loc, const std::string& name, std::int64_t v);
void write_attr(hid_t loc, const std::string& name, const std::string& v);
[[nodiscard]] double read_attr_double(hid_t loc, const std::string& name);
[[nodiscard]] std::int64_t read_attr_int64(hid_t loc, const std::string& name);
[[nodiscard]] std::string read_attr_string(hid_t loc, const std::string& name);

// SimParams as attributes of one group: every field under its own name, with "<name>_units"
// where a unit applies and "<name>_name" for enums (e.g. kernel = 5, kernel_name =
// "wendland"); bools as 0/1; c0 is added for reading, not read back. read_params throws
// InputError naming the file and the missing attribute.
void write_params(hid_t loc, const SimParams& p);
[[nodiscard]] SimParams read_params(hid_t loc);

// "0.1.0 (git 2910f05abcde)" from SPHJET_VERSION / SPHJET_GIT_HASH.
[[nodiscard]] std::string code_version();
[[nodiscard]] std::string git_hash();
// Current UTC time, ISO 8601.
[[nodiscard]] std::string utc_now();

}  // namespace sphjet::h5
