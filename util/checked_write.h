// The one way Phellem puts bytes in a file. Every call is checked: the writes (all of the bytes,
// through short writes and EINTR), fsync (where a full disk or a quota may first show) and
// close. Image, glTF, JSON and HTML writers build their bytes in memory and hand them here,
// because the libraries' own file writers do not all report a full disk.
#pragma once

#include <string>
#include <string_view>

namespace phellem {

// Creates or truncates `file` and writes `bytes` to it. A failure is
// UserError(path, "write", why), `path` being the name the user gave (`file` is usually its
// temporary), and leaves `file` to the caller to remove.
void write_file_checked(const std::string& path, const std::string& file, std::string_view bytes);

}  // namespace phellem
