// The three kinds of failure (STYLE.md, practice 5): UserError for bad input (exit 2),
// anything else that escapes to main is an internal failure (exit 1).
#pragma once

#include <stdexcept>
#include <string>

namespace phellem {

// Bad user input: a scene, a mesh, an image, a parameter out of range. `file` names the file,
// `where` the JSON path or glTF element, `what` what is wrong and what is allowed.
class UserError : public std::runtime_error {
 public:
  UserError(std::string file, std::string where, std::string what)
      : std::runtime_error(compose(file, where, what)),
        file_(std::move(file)), where_(std::move(where)), what_(std::move(what)) {}
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& detail() const { return what_; }

 private:
  static std::string compose(const std::string& f, const std::string& w, const std::string& x) {
    std::string s = f.empty() ? std::string("<command line>") : f;
    if (!w.empty()) s += ": " + w;
    return s + ": " + x;
  }
  std::string file_, where_, what_;
};

}  // namespace phellem
