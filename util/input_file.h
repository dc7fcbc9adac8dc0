// Input files are read only when they are regular files (or symbolic links to one): a FIFO
// blocks its reader until some writer comes, which may be never; a character device such as
// /dev/zero never ends; a folder has no bytes. Every opener of a user's file (scenes, meshes,
// material libraries, glTF buffers, images) asks here before it opens anything.
#pragma once

#include <optional>
#include <string>

namespace phellem {

// What a file of `mode` (stat's st_mode) that is not a regular file is, for messages: "a
// folder", "a FIFO", "a character device", "a block device", "a socket".
const char* file_kind(unsigned mode);

// Why `path` cannot be read as an input file, as it reads after the file's name: "does not
// exist", "is a folder", "is not a regular file (a FIFO)" (or a character device, a block
// device, a socket); nullopt when it is a regular file. stat follows symbolic links, so a link
// to a regular file is one.
std::optional<std::string> input_file_problem(const std::string& path);

// The same as a message: "file not found: <path>", or "<path> is not a regular file (a FIFO);
// <kind> is read from a regular file", where `kind` names what the file is ("an image").
std::optional<std::string> input_file_message(const std::string& path, const std::string& kind);

// Throws UserError(file, where, input_file_message(path, kind)) when there is one; the path is
// left out of the message when it is `file` itself.
void require_input_file(const std::string& path, const std::string& file, const std::string& where, const std::string& kind);

}  // namespace phellem
