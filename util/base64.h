// Standard base64 (RFC 4648, padded): data: URIs in HTML reports and test glTF files.
#pragma once

#include <cstddef>
#include <string>

namespace phellem {

std::string base64(const unsigned char* data, size_t size);

}  // namespace phellem
