#include "io/h5_util.hpp"

#include <algorithm>
#include <cstring>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

#include "io/file_write.hpp"
#include "model/case_params.hpp"
#include "model/errors.hpp"

#ifndef SPHJET_VERSION
#define SPHJET_VERSION "unknown"
#endif
#include "sphjet_git_hash.h"  // generated at build time (cpp_driver/git_hash.cmake)

namespace sphjet::h5 {

static_assert(sizeof(int) == sizeof(std::int32_t), "ParticleSet stores int arrays as int32");

namespace {

// Chunk of a checksummed dataset: 2^18 values (2 MiB of doubles).
constexpr hsize_t kChunk = hsize_t{1} << 18;

struct ErrorWalk {
    std::string innermost;
    std::string api;
};

herr_t walk_cb(unsigned n, const H5E_error2_t* e, void* data) {
    auto* w = static_cast<ErrorWalk*>(data);
    const std::string desc = e->desc ? e->desc : "";
    if (n == 0) w->innermost = desc;
    w->api = std::string(e->func_name ? e->func_name : "") + ": " + desc;
    return 0;
}

std::string with_h5(const std::string& problem, const std::string& h5) {
    return h5.empty() ? problem : problem + " (HDF5: " + h5 + ")";
}

// The HDF5 message is taken first: where() calls into HDF5, which clears the error stack.
[[noreturn]] void fail(const std::string& at, const std::string& problem) {
    const std::string h5 = last_error();
    throw InputError(at, with_h5(problem, h5));
}

[[noreturn]] void fail(hid_t loc, const std::string& name, const std::string& problem) {
    const std::string h5 = last_error();
    throw InputError(where(loc, name), with_h5(problem, h5));
}

void check(herr_t status, hid_t loc, const std::string& name, const std::string& problem) {
    if (status < 0) fail(loc, name, problem);
}

std::string where_attr(hid_t loc, const std::string& name) {
    return where(loc) + " attribute '" + name + "'";
}

[[noreturn]] void fail_attr(hid_t loc, const std::string& name, const std::string& problem) {
    const std::string h5 = last_error();
    throw InputError(where_attr(loc, name), with_h5(problem, h5));
}

void check_attr(herr_t status, hid_t loc, const std::string& name, const std::string& problem) {
    if (status < 0) fail_attr(loc, name, problem);
}

template <class T>
void write_array_impl(hid_t loc, const std::string& name, std::span<const T> v, hid_t file_type,
                      hid_t mem_type, const char* units, Layout layout) {
    QuietErrors quiet;
    const hsize_t n = v.size();
    Dataspace space(H5Screate_simple(1, &n, nullptr));
    PropList dcpl(H5Pcreate(H5P_DATASET_CREATE));
    if (space < 0 || dcpl < 0) fail(loc, name, "cannot create dataspace");
    if (layout == Layout::Checksummed && n > 0) {
        const hsize_t chunk = std::min(n, kChunk);
        check(H5Pset_chunk(dcpl, 1, &chunk), loc, name, "cannot set chunking");
        check(H5Pset_fletcher32(dcpl), loc, name, "cannot set the Fletcher-32 filter");
    }
    Dataset ds(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot create dataset");
    if (n > 0) {
        check(H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), loc, name,
              "cannot write dataset");
    }
    if (units != nullptr) write_attr(ds, "units", std::string(units));
}

template <class T>
std::vector<T> read_impl(hid_t loc, const std::string& name, std::optional<std::size_t> expected,
                         H5T_class_t cls, hid_t mem_type, const char* type_name) {
    QuietErrors quiet;
    if (!has_link(loc, name)) throw InputError(where(loc, name), "missing dataset");
    Dataset ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot open dataset");
    Datatype type(H5Dget_type(ds));
    if (type < 0 || H5Tget_class(type) != cls || H5Tget_size(type) > sizeof(T)) {
        throw InputError(where(loc, name), "wrong type", std::string("a dataset of ") + type_name,
                         "another type");
    }
    Dataspace space(H5Dget_space(ds));
    if (space < 0) fail(loc, name, "cannot read the dataspace");
    if (H5Sget_simple_extent_ndims(space) != 1) {
        throw InputError(where(loc, name), "wrong shape", "a 1-D dataset",
                         std::to_string(H5Sget_simple_extent_ndims(space)) + " dimensions");
    }
    hsize_t n = 0;
    H5Sget_simple_extent_dims(space, &n, nullptr);
    if (expected && n != *expected) {
        throw InputError(where(loc, name), "wrong length", std::to_string(*expected) + " values",
                         std::to_string(n));
    }
    std::vector<T> out(n);
    if (n > 0) {
        check(H5Dread(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), loc, name,
              "cannot read dataset (file truncated or corrupt?)");
    }
    return out;
}

Attribute create_attr(hid_t loc, const std::string& name, hid_t type) {
    if (H5Aexists(loc, name.c_str()) > 0) H5Adelete(loc, name.c_str());
    Dataspace space(H5Screate(H5S_SCALAR));
    Attribute a(H5Acreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT));
    if (a < 0) fail_attr(loc, name, "cannot create attribute");
    return a;
}

Attribute open_attr(hid_t loc, const std::string& name) {
    if (!has_attr(loc, name)) throw InputError(where_attr(loc, name), "missing attribute");
    Attribute a(H5Aopen(loc, name.c_str(), H5P_DEFAULT));
    if (a < 0) fail_attr(loc, name, "cannot open attribute");
    return a;
}

// Bob Jenkins' lookup3 hash (hashlittle, public domain), which HDF5 uses for its metadata
// checksums (H5_checksum_lookup3 with initval 0).
std::uint32_t lookup3(const unsigned char* k, std::size_t length) {
    const auto rot = [](std::uint32_t x, int r) { return (x << r) | (x >> (32 - r)); };
    const auto word = [](const unsigned char* p) {
        return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
               std::uint32_t{p[3]} << 24;
    };
    std::uint32_t a, b, c;
    a = b = c = 0xdeadbeefu + static_cast<std::uint32_t>(length);
    while (length > 12) {
        a += word(k), b += word(k + 4), c += word(k + 8);
        a -= c, a ^= rot(c, 4), c += b;
        b -= a, b ^= rot(a, 6), a += c;
        c -= b, c ^= rot(b, 8), b += a;
        a -= c, a ^= rot(c, 16), c += b;
        b -= a, b ^= rot(a, 19), a += c;
        c -= b, c ^= rot(b, 4), b += a;
        length -= 12, k += 12;
    }
    if (length == 0) return c;
    unsigned char tail[12] = {};
    std::memcpy(tail, k, length);
    a += word(tail), b += word(tail + 4), c += word(tail + 8);
    c ^= b, c -= rot(b, 14);
    a ^= c, a -= rot(c, 11);
    b ^= a, b -= rot(a, 25);
    c ^= b, c -= rot(b, 16);
    a ^= c, a -= rot(c, 4);
    b ^= a, b -= rot(a, 14);
    c ^= b, c -= rot(b, 24);
    return c;
}

// The image of a file still open for writing carries "open for write" in the status flags of
// its superblock (version 2 and 3, which have a checksum). H5Fget_file_image clears those
// flags in the copy, but HDF5 1.10 leaves the superblock checksum as it was, so readers
// refuse the file ("incorrect metadata checksum"). This clears the flags and sets the
// checksum afresh (a no-op where HDF5 already did both).
void finish_superblock(std::string& image) {
    static constexpr unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    auto* p = reinterpret_cast<unsigned char*>(image.data());
    if (image.size() < 12 || std::memcmp(p, kSignature, 8) != 0 || p[8] < 2) return;
    const std::size_t body = 12 + 4 * std::size_t{p[9]};  // four addresses of p[9] bytes
    if (image.size() < body + 4) return;
    p[11] = 0;  // status flags: closed
    const std::uint32_t sum = lookup3(p, body);
    for (int i = 0; i < 4; ++i) p[body + i] = static_cast<unsigned char>(sum >> (8 * i));
}

// One memory buffer per thread that the in-memory file of a snapshot or checkpoint lives in,
// kept from one file to the next (HDF5's core driver allocates through these file image
// callbacks). A fresh buffer of tens of MB costs more in page faults than the write to disk
// (0.5 s per 80 MB on our test machine); a reused one costs a memcpy. After H5Fclose the
// buffer holds the finished file, superblock included, which write_file writes out.
struct ImagePool {
    struct FreeDeleter {
        void operator()(char* p) const { std::free(p); }
    };
    std::unique_ptr<char, FreeDeleter> mem;
    std::size_t cap = 0;
    bool reserved = false;  // a file created by create_file uses mem
    hid_t owner = H5I_INVALID_HID;
    bool closed = false;    // that file was closed: mem holds its finished image
};

ImagePool& image_pool() {
    thread_local ImagePool pool;
    return pool;
}

void* pool_realloc(void* ptr, std::size_t size, H5FD_file_image_op_t, void* udata) {
    auto* pool = static_cast<ImagePool*>(udata);
    if (ptr != nullptr && ptr != pool->mem.get()) return std::realloc(ptr, size);
    if (size > pool->cap) {
        char* grown = static_cast<char*>(std::realloc(pool->mem.get(), size));
        if (grown == nullptr) return nullptr;
        (void)pool->mem.release();
        pool->mem.reset(grown);
        pool->cap = size;
    }
    pool->closed = false;
    return pool->mem.get();
}

void* pool_malloc(std::size_t size, H5FD_file_image_op_t op, void* udata) {
    return pool_realloc(nullptr, size, op, udata);
}

void* pool_memcpy(void* dest, const void* src, std::size_t size, H5FD_file_image_op_t, void*) {
    return std::memcpy(dest, src, size);
}

herr_t pool_free(void* ptr, H5FD_file_image_op_t, void* udata) {
    auto* pool = static_cast<ImagePool*>(udata);
    if (ptr != pool->mem.get()) {
        std::free(ptr);
        return 0;
    }
    pool->reserved = false;
    pool->closed = true;  // kept: write_file reads the finished image from it
    return 0;
}

void* pool_udata_copy(void* udata) { return udata; }
herr_t pool_udata_free(void*) { return 0; }

// The length of a finished HDF5 image from its superblock (version 2 or 3, which this code
// writes: end-of-file address after the base, extension and ... addresses), or 0 if unknown.
std::size_t image_length(const char* mem, std::size_t cap) {
    const auto* p = reinterpret_cast<const unsigned char*>(mem);
    static constexpr unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    if (cap < 12 || std::memcmp(p, kSignature, 8) != 0 || p[8] < 2 || p[9] == 0 || p[9] > 8)
        return 0;
    const std::size_t o = p[9];
    const std::size_t at = 12 + 2 * o;  // after the base and the extension addresses
    if (cap < at + o) return 0;
    std::uint64_t eof = 0;
    for (std::size_t i = 0; i < o; ++i) eof |= std::uint64_t{p[at + i]} << (8 * i);
    return eof <= cap ? static_cast<std::size_t>(eof) : 0;
}

}  // namespace

QuietErrors::QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

std::string last_error() {
    ErrorWalk w;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, walk_cb, &w);
    if (w.api.empty()) return w.innermost;
    if (w.innermost.empty() || w.api.find(w.innermost) != std::string::npos) return w.api;
    return w.api + ": " + w.innermost;
}

std::string where(hid_t loc, const std::string& name) {
    std::string file = "?", obj;
    if (const ssize_t n = H5Fget_name(loc, nullptr, 0); n > 0) {
        file.assign(static_cast<std::size_t>(n) + 1, '\0');
        H5Fget_name(loc, file.data(), file.size());
        file.resize(static_cast<std::size_t>(n));
    }
    if (const ssize_t n = H5Iget_name(loc, nullptr, 0); n > 0) {
        obj.assign(static_cast<std::size_t>(n) + 1, '\0');
        H5Iget_name(loc, obj.data(), obj.size());
        obj.resize(static_cast<std::size_t>(n));
    }
    if (obj == "/") obj.clear();
    if (name.empty()) return file + ": " + (obj.empty() ? "/" : obj);
    return file + ": " + obj + "/" + name;
}

File create_file(const std::filesystem::path& path, std::size_t size_hint) {
    QuietErrors quiet;
    PropList fapl(H5Pcreate(H5P_FILE_ACCESS));
    // In memory, grown in steps of the expected size (so that it is rarely copied).
    const std::size_t increment = std::max<std::size_t>(size_hint + size_hint / 8 + (64u << 10),
                                                        1u << 20);
    if (fapl < 0 || H5Pset_fapl_core(fapl, increment, false) < 0) {
        fail(path.string(), "cannot set up an in-memory HDF5 file");
    }
    // The thread's reusable buffer, unless another file of this thread holds it (that one
    // gets memory of its own, and write_file takes its image with H5Fget_file_image).
    ImagePool& pool = image_pool();
    const bool use_pool = !pool.reserved;
    if (use_pool) {
        H5FD_file_image_callbacks_t cb{pool_malloc, pool_memcpy,     pool_realloc,   pool_free,
                                       pool_udata_copy, pool_udata_free, &pool};
        if (H5Pset_file_image_callbacks(fapl, &cb) < 0) {
            fail(path.string(), "cannot set up an in-memory HDF5 file");
        }
    }
    // Low bound 1.8: every object in the oldest format that has checksummed metadata; high
    // bound latest: allows the virtual datasets (1.10) of write_vec3_view.
    H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    if (use_pool) pool.reserved = true;
    File f(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl));
    if (f < 0) {
        if (use_pool) pool.reserved = false;
        fail(path.string(), "cannot create HDF5 file");
    }
    if (use_pool) pool.owner = f.get();
    return f;
}

File open_file(const std::filesystem::path& path) {
    QuietErrors quiet;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw InputError(path.string(), "no such file");
    }
    if (H5Fis_hdf5(path.c_str()) <= 0) {
        throw InputError(path.string(), "not an HDF5 file (truncated or corrupt?)");
    }
    File f(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (f < 0) fail(path.string(), "cannot open HDF5 file (truncated or corrupt?)");
    return f;
}

void write_file(File& f, const std::filesystem::path& path, std::string_view what) {
    ImagePool& pool = image_pool();
    if (pool.reserved && pool.owner == f.get()) {
        // The file lives in the thread's buffer: close it (HDF5 finishes the superblock),
        // then write the buffer out.
        {
            QuietErrors quiet;
            const hid_t id = f.release();
            if (H5Fclose(id) < 0) fail(path.string(), "cannot close the in-memory file");
        }
        const std::size_t n = pool.closed ? image_length(pool.mem.get(), pool.cap) : 0;
        if (n == 0) throw InputError(path.string(), "cannot find the end of the in-memory file");
        write_file_atomically(path, std::string_view(pool.mem.get(), n), what);
        return;
    }
    std::string image;
    {
        QuietErrors quiet;
        if (H5Fflush(f, H5F_SCOPE_GLOBAL) < 0) fail(path.string(), "cannot finish the file");
        const ssize_t n = H5Fget_file_image(f, nullptr, 0);
        if (n < 0) fail(path.string(), "cannot take the file image");
        image.resize(static_cast<std::size_t>(n));
        if (H5Fget_file_image(f, image.data(), image.size()) != n) {
            fail(path.string(), "cannot take the file image");
        }
        const hid_t id = f.release();
        if (H5Fclose(id) < 0) fail(path.string(), "cannot close the in-memory file");
    }
    finish_superblock(image);
    write_file_atomically(path, image, what);
}

Group create_group(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    Group g(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (g < 0) fail(loc, name, "cannot create group");
    return g;
}

Group open_group(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    if (!has_link(loc, name)) throw InputError(where(loc, name), "missing group");
    Group g(H5Gopen2(loc, name.c_str(), H5P_DEFAULT));
    if (g < 0) fail(loc, name, "cannot open group");
    return g;
}

bool has_link(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    return H5Lexists(loc, name.c_str(), H5P_DEFAULT) > 0;
}

bool has_attr(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    return H5Aexists(loc, name.c_str()) > 0;
}

std::vector<std::string> link_names(hid_t loc) {
    QuietErrors quiet;
    std::vector<std::string> names;
    auto cb = [](hid_t, const char* n, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->emplace_back(n);
        return 0;
    };
    hsize_t idx = 0;
    if (H5Literate(loc, H5_INDEX_NAME, H5_ITER_INC, &idx, cb, &names) < 0) {
        fail(loc, {}, "cannot list group");
    }
    return names;
}

void write_array(hid_t loc, const std::string& name, std::span<const double> v, const char* units,
                 Layout layout) {
    write_array_impl(loc, name, v, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, units, layout);
}

void write_array(hid_t loc, const std::string& name, std::span<const std::int32_t> v,
                 const char* units, Layout layout) {
    write_array_impl(loc, name, v, H5T_STD_I32LE, H5T_NATIVE_INT32, units, layout);
}

void write_array(hid_t loc, const std::string& name, std::span<const std::int64_t> v,
                 const char* units, Layout layout) {
    write_array_impl(loc, name, v, H5T_STD_I64LE, H5T_NATIVE_INT64, units, layout);
}

void write_vec3_view(hid_t loc, const std::string& name, const std::array<std::string, 3>& sources,
                     std::size_t n_values) {
    QuietErrors quiet;
    const hsize_t n = n_values;
    const hsize_t dims[2] = {n, 3};
    Dataspace vspace(H5Screate_simple(2, dims, nullptr));
    PropList dcpl(H5Pcreate(H5P_DATASET_CREATE));
    const double zero = 0.0;
    check(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &zero), loc, name,
          "cannot set the fill value");
    if (n > 0) {
        Dataspace src(H5Screate_simple(1, &n, nullptr));
        for (hsize_t k = 0; k < 3; ++k) {
            if (sources[k].empty()) continue;  // unmapped: reads the fill value
            const hsize_t start[2] = {0, k}, count[2] = {n, 1};
            check(H5Sselect_hyperslab(vspace, H5S_SELECT_SET, start, nullptr, count, nullptr), loc,
                  name, "cannot select a column");
            check(H5Pset_virtual(dcpl, vspace, ".", sources[k].c_str(), src), loc, name,
                  "cannot map " + sources[k]);
        }
        H5Sselect_all(vspace);
    }
    Dataset ds(
        H5Dcreate2(loc, name.c_str(), H5T_IEEE_F64LE, vspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot create virtual dataset");
}

void write_vec3_array(hid_t loc, const std::string& name, std::span<const double> xyz,
                      const char* units) {
    QuietErrors quiet;
    const hsize_t dims[2] = {xyz.size() / 3, 3};
    if (dims[0] * 3 != xyz.size()) fail(loc, name, "not a multiple of 3 values");
    Dataspace space(H5Screate_simple(2, dims, nullptr));
    if (space < 0) fail(loc, name, "cannot create dataspace");
    Dataset ds(H5Dcreate2(loc, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot create dataset");
    if (!xyz.empty()) {
        check(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, xyz.data()), loc,
              name, "cannot write dataset");
    }
    if (units != nullptr) write_attr(ds, "units", std::string(units));
}

void write_repeat_view(hid_t loc, const std::string& name, const std::string& source, hid_t type,
                       std::size_t n_values, std::size_t copies) {
    QuietErrors quiet;
    const hsize_t n = n_values, total = n_values * copies;
    Dataspace vspace(H5Screate_simple(1, &total, nullptr));
    PropList dcpl(H5Pcreate(H5P_DATASET_CREATE));
    if (vspace < 0 || dcpl < 0) fail(loc, name, "cannot create dataspace");
    if (n > 0) {
        Dataspace src(H5Screate_simple(1, &n, nullptr));
        for (hsize_t k = 0; k < copies; ++k) {
            const hsize_t start = k * n;
            check(H5Sselect_hyperslab(vspace, H5S_SELECT_SET, &start, nullptr, &n, nullptr), loc,
                  name, "cannot select a copy");
            check(H5Pset_virtual(dcpl, vspace, ".", source.c_str(), src), loc, name,
                  "cannot map " + source);
        }
        H5Sselect_all(vspace);
    }
    Dataset ds(H5Dcreate2(loc, name.c_str(), type, vspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot create virtual dataset");
}

void write_iota(hid_t loc, const std::string& name, std::size_t n_values) {
    QuietErrors quiet;
    std::vector<std::int64_t> v(n_values);
    for (std::size_t i = 0; i < n_values; ++i) v[i] = static_cast<std::int64_t>(i);
    const hsize_t n = n_values;
    Dataspace space(H5Screate_simple(1, &n, nullptr));
    PropList dcpl(H5Pcreate(H5P_DATASET_CREATE));
    if (n > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
        const hsize_t chunk = std::min(n, kChunk);
        check(H5Pset_chunk(dcpl, 1, &chunk), loc, name, "cannot set chunking");
        check(H5Pset_shuffle(dcpl), loc, name, "cannot set the shuffle filter");
        check(H5Pset_deflate(dcpl, 1), loc, name, "cannot set the deflate filter");
    }
    Dataset ds(H5Dcreate2(loc, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    if (ds < 0) fail(loc, name, "cannot create dataset");
    if (n > 0) {
        check(H5Dwrite(ds, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), loc, name,
              "cannot write dataset");
    }
}

std::vector<double> read_doubles(hid_t loc, const std::string& name,
                                 std::optional<std::size_t> expected_size) {
    return read_impl<double>(loc, name, expected_size, H5T_FLOAT, H5T_NATIVE_DOUBLE, "doubles");
}

std::vector<std::int32_t> read_int32(hid_t loc, const std::string& name,
                                     std::optional<std::size_t> expected_size) {
    return read_impl<std::int32_t>(loc, name, expected_size, H5T_INTEGER, H5T_NATIVE_INT32,
                                   "32-bit integers");
}

std::vector<std::int64_t> read_int64(hid_t loc, const std::string& name,
                                     std::optional<std::size_t> expected_size) {
    return read_impl<std::int64_t>(loc, name, expected_size, H5T_INTEGER, H5T_NATIVE_INT64,
                                   "64-bit integers");
}

void write_attr(hid_t loc, const std::string& name, double v) {
    QuietErrors quiet;
    Attribute a = create_attr(loc, name, H5T_IEEE_F64LE);
    check_attr(H5Awrite(a, H5T_NATIVE_DOUBLE, &v), loc, name, "cannot write attribute");
}

void write_attr(hid_t loc, const std::string& name, std::int64_t v) {
    QuietErrors quiet;
    Attribute a = create_attr(loc, name, H5T_STD_I64LE);
    check_attr(H5Awrite(a, H5T_NATIVE_INT64, &v), loc, name, "cannot write attribute");
}

void write_attr(hid_t loc, const std::string& name, const std::string& v) {
    QuietErrors quiet;
    Datatype type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type, v.size() + 1);
    H5Tset_strpad(type, H5T_STR_NULLTERM);
    H5Tset_cset(type, H5T_CSET_UTF8);
    Attribute a = create_attr(loc, name, type);
    check_attr(H5Awrite(a, type, v.c_str()), loc, name, "cannot write attribute");
}

double read_attr_double(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    Attribute a = open_attr(loc, name);
    Datatype t(H5Aget_type(a));
    const H5T_class_t c = H5Tget_class(t);
    if (c != H5T_FLOAT && c != H5T_INTEGER) {
        throw InputError(where_attr(loc, name), "wrong type", "a number", "another type");
    }
    double v = 0.0;
    check_attr(H5Aread(a, H5T_NATIVE_DOUBLE, &v), loc, name, "cannot read attribute");
    return v;
}

std::int64_t read_attr_int64(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    Attribute a = open_attr(loc, name);
    Datatype t(H5Aget_type(a));
    if (H5Tget_class(t) != H5T_INTEGER) {
        throw InputError(where_attr(loc, name), "wrong type", "an integer", "another type");
    }
    std::int64_t v = 0;
    check_attr(H5Aread(a, H5T_NATIVE_INT64, &v), loc, name, "cannot read attribute");
    return v;
}

std::string read_attr_string(hid_t loc, const std::string& name) {
    QuietErrors quiet;
    Attribute a = open_attr(loc, name);
    Datatype t(H5Aget_type(a));
    if (H5Tget_class(t) != H5T_STRING) {
        throw InputError(where_attr(loc, name), "wrong type", "a string", "another type");
    }
    const H5T_cset_t cset = H5Tget_cset(t);  // HDF5 does not convert between ASCII and UTF-8
    if (H5Tis_variable_str(t) > 0) {         // as h5py writes them
        Datatype mem(H5Tcopy(H5T_C_S1));
        H5Tset_size(mem, H5T_VARIABLE);
        H5Tset_cset(mem, cset);
        char* s = nullptr;
        check_attr(H5Aread(a, mem, &s), loc, name, "cannot read attribute");
        std::string out = s ? s : "";
        H5free_memory(s);
        return out;
    }
    const std::size_t size = H5Tget_size(t);
    Datatype mem(H5Tcopy(H5T_C_S1));
    H5Tset_size(mem, size + 1);
    H5Tset_strpad(mem, H5T_STR_NULLTERM);
    H5Tset_cset(mem, cset);
    std::string buf(size + 1, '\0');
    check_attr(H5Aread(a, mem, buf.data()), loc, name, "cannot read attribute");
    buf.resize(std::strlen(buf.c_str()));
    return buf;
}

std::string code_version() {
    return std::string(SPHJET_VERSION) + " (git " + SPHJET_GIT_HASH + ")";
}

std::string git_hash() { return SPHJET_GIT_HASH; }

std::string utc_now() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

}  // namespace sphjet::h5

// ---- SimParams --------------------------------------------------------------------------

namespace sphjet::h5 {

namespace {

// The rows of SimParams' members (model/case_params.hpp), in the order of its declaration:
// the order of the attributes in the files.
const std::vector<const Param*>& param_rows() {
    static const std::vector<const Param*> rows = [] {
        std::vector<const Param*> out;
        for (const Param& r : case_params())
            if (!r.attr.empty()) out.push_back(&r);
        const SimParams p;
        const auto at = [&p](const Param* r) { return static_cast<const char*>(r->member.address(&p)); };
        std::stable_sort(out.begin(), out.end(), [&at](const Param* a, const Param* b) { return at(a) < at(b); });
        return out;
    }();
    return rows;
}

// The "<name>_name" attribute of an enum parameter: its case-file name (or the row's
// h5_choices name), "unknown" for a value outside the table.
std::string enum_name(const Param& r, std::int64_t v) {
    return choice_name(r.h5_choices.empty() ? r.choices : r.h5_choices, v);
}

}  // namespace

void write_params(hid_t loc, const SimParams& p) {
    for (const Param* r : param_rows()) {
        const std::string name(r->attr);
        const Member& m = r->member;
        if (m.store == Member::Store::Float) {
            write_attr(loc, name, m.get_f(&p));
        } else {
            write_attr(loc, name, m.get_i(&p));
            if (m.store == Member::Store::Enum) write_attr(loc, name + "_name", enum_name(*r, m.get_i(&p)));
        }
        const std::string_view units = attr_unit(*r, p);
        if (!units.empty()) write_attr(loc, name + "_units", std::string(units));
    }
    if (p.B > 0.0 && p.rho0 > 0.0) {
        write_attr(loc, "c0", p.c0());
        write_attr(loc, "c0_units", std::string("m/s"));
    }
}

SimParams read_params(hid_t loc) {
    SimParams p;
    for (const Param* r : param_rows()) {
        const std::string name(r->attr);
        const Member& m = r->member;
        // Added after files were first written: files without it keep the default.
        if (r->h5_optional && !has_attr(loc, name)) continue;
        if (m.store == Member::Store::Float) {
            m.set_f(&p, read_attr_double(loc, name));
        } else if (m.store == Member::Store::Enum) {
            const std::int64_t v = read_attr_int64(loc, name);
            if (enum_name(*r, v) == "unknown")
                throw InputError(where_attr(loc, name), "unknown value", "a value this code knows",
                                 std::to_string(static_cast<int>(v)));
            m.set_i(&p, v);
        } else if (m.store == Member::Store::Bool) {
            m.set_i(&p, read_attr_int64(loc, name) != 0 ? 1 : 0);
        } else {
            m.set_i(&p, read_attr_int64(loc, name));
        }
    }
    return p;
}

}  // namespace sphjet::h5
