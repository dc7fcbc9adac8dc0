// Strict JSON access for scene parsing: every read knows its JSON path, every value is
// type-checked and finite, and keys that nobody read are reported as errors (STYLE.md, 4).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "util/errors.h"
#include "util/math.h"

namespace phellem {

// The one range of every seed, in scenes and on the command line.
inline constexpr const char* kSeedRange = "[0, 18446744073709551615]";

// Parses text into JSON, turning syntax errors into UserError with line and column, and
// refusing duplicate keys and numbers that overflow a double at their JSON paths.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

class JsonValue;

// An object whose keys are consumed by name; finish() rejects the unread ones.
class JsonObject {
 public:
  JsonObject(const nlohmann::json& j, std::string file, std::string path);

  bool has(const std::string& key) const { return j_->contains(key); }
  JsonValue at(const std::string& key);                  // required key
  std::optional<JsonValue> get(const std::string& key);  // optional key

  float number(const std::string& key, float fallback);
  float number(const std::string& key);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string string(const std::string& key);
  Vec3f vec3(const std::string& key, const Vec3f& fallback);
  Vec3f vec3(const std::string& key);
  Color color(const std::string& key, const Color& fallback);

  // Throws for every key present but not read; call once parsing of the object is done.
  void finish() const;

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  const nlohmann::json* j_;
  std::string file_, path_;
  std::set<std::string> used_;
};

class JsonValue {
 public:
  JsonValue(const nlohmann::json& j, std::string file, std::string path)
      : j_(&j), file_(std::move(file)), path_(std::move(path)) {}

  float number() const;
  float positive() const;             // > 0
  float non_negative() const;         // >= 0
  int integer() const;                // a 32-bit signed integer
  int integer(int lo, int hi) const;  // an integer in [lo, hi]; the message states the range
  uint64_t seed() const;              // an integer in [0, 2^64 - 1], read exactly (kSeedRange)
  bool boolean() const;
  std::string string() const;
  Vec2f vec2() const;
  Vec3f vec3() const;
  Color color() const;  // 3 non-negative numbers
  std::vector<float> numbers() const;
  bool is_object() const { return j_->is_object(); }
  bool is_string() const { return j_->is_string(); }
  bool is_array() const { return j_->is_array(); }
  bool is_number() const { return j_->is_number(); }
  bool is_bool() const { return j_->is_boolean(); }
  JsonObject object() const;
  std::vector<JsonValue> array() const;
  const nlohmann::json& raw() const { return *j_; }

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const { throw UserError(file_, path_, what); }

 private:
  const nlohmann::json* j_;
  std::string file_, path_;
};

}  // namespace phellem
