#include "io/image_decode.h"

#include "util/errors.h"

namespace phellem {

std::optional<std::string> decode_image(OIIO::ImageInput& in, int chbegin, int chend, OIIO::TypeDesc type, void* data) {
  const bool decoded = in.read_image(0, 0, chbegin, chend, type, data);
  // A decoder's warning (a truncated or corrupt JPEG) leaves read_image true but an error set.
  if (decoded && !in.has_error()) return std::nullopt;
  std::string why = in.geterror();
  while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
  if (why.empty()) why = "the decoder failed without saying why";
  return "the file is damaged or cut short (" + printable(why) + ")";
}

}  // namespace phellem
