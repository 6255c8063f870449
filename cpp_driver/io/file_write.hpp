// Output files that survive a full disk.
//
// Every file a run writes goes through one of these two writers:
//   write_file_atomically  the whole content into PATH.tmp, fsync, rename over PATH, fsync of
//                          the directory: after a failure PATH is the previous version (or
//                          absent), PATH.tmp is gone, and after a machine crash PATH is
//                          either the old file or the complete new one.
//   AppendFile             rows appended to a text file (DT, steps.txt, run.log): each append
//                          lands whole, or the file is cut back to its previous length. Rows
//                          are not fsynced one by one: a machine crash may lose the last ones,
//                          and a resumed run cuts DT and steps.txt back to its checkpoint.
// The HDF5 files (snapshots, run.h5, checkpoint.h5) are built in memory and handed to
// write_file_atomically (io/h5_util.hpp), so HDF5 itself never meets a full disk: HDF5 1.10.8
// crashes at exit (H5F__close_cb) after an H5Fclose that failed for want of space, and keeps
// the file's descriptor, and so its blocks, until then.
//
// A failure throws WriteError (model/errors.hpp) naming the file and the cause from errno,
// e.g. "run/snap_000012.h5: cannot write the snapshot: No space left on device; expected room
// for 160 kB on the file system, found 12 kB free".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sphjet {

// Writes bytes to path through path + tmp_suffix (see above). what names the file's role in
// messages ("the snapshot", "PART file"). Throws WriteError; the temporary file is removed.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           std::string_view what, std::string_view tmp_suffix = ".tmp");

// A text file that grows by whole rows.
class AppendFile {
public:
    // keep: keep the existing content (resume), cutting off a last row without its newline
    // (half-written by an older build or a machine crash); otherwise start the file anew.
    // header is written when the file is empty. Throws WriteError.
    AppendFile(std::filesystem::path path, std::string what, bool keep,
               std::string_view header = {});
    ~AppendFile();
    AppendFile(const AppendFile&) = delete;
    AppendFile& operator=(const AppendFile&) = delete;
    AppendFile(AppendFile&& o) noexcept;
    AppendFile& operator=(AppendFile&& o) noexcept;

    // Appends text (normally whole lines). On failure the file is cut back to its length
    // before the call and WriteError is thrown; the file stays usable for the next append.
    void append(std::string_view text);

    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] std::uintmax_t size() const { return size_; }

private:
    std::filesystem::path path_;
    std::string what_;
    int fd_ = -1;
    std::uintmax_t size_ = 0;
};

// Throws the WriteError for a failed write of `bytes` bytes to path (err = errno; 0 unknown).
// For ENOSPC and EDQUOT the message adds the space needed and the space free.
[[noreturn]] void throw_write_error(const std::filesystem::path& path, std::string_view what,
                                    int err, std::uintmax_t bytes, std::string_view detail = {});

// Removes the temporary files of the writers above (names ending in ".tmp" or ".tmp-sphjet")
// from dir, which must be a directory sphjet owns (a run directory); returns their names.
// Never throws.
std::vector<std::string> remove_temporaries(const std::filesystem::path& dir) noexcept;

// "512 B", "12 kB", "3.4 MB", "1.2 GB" (powers of 1000).
[[nodiscard]] std::string human_bytes(std::uintmax_t n);

}  // namespace sphjet
