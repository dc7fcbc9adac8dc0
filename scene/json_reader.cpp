#include "scene/json_reader.h"

#include <charconv>
#include <cmath>

#include "util/json_nesting.h"

namespace phellem {

namespace {

std::string type_name(const nlohmann::json& j) { return j.type_name(); }

// The largest magnitude a scene number may have: it must fit a float (FLT_MAX ≈ 3.4028e38).
constexpr double kMaxNumber = 3.4e38;
const char* kNumberRange = "valid range [-3.4e38, 3.4e38]";

// A number as a person would write it: shortest round-trip form, exponent without '+' or
// leading zeros (1e300, not 1e+300).
std::string format_number(double d) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  std::string s(buf, r.ptr);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + sign + exponent;
}

// What a value is, for "found ..." in a message: the number itself, or its type.
std::string found(const nlohmann::json& j) {
  if (j.is_number_unsigned()) return std::to_string(j.get<uint64_t>());
  if (j.is_number_integer()) return std::to_string(j.get<int64_t>());
  if (j.is_number_float()) return format_number(j.get<double>());
  return type_name(j);
}

// Follows the JSON path of the value being parsed through the parser's callback events, so
// that errors the parser itself raises (duplicate keys, numbers that overflow a double) can
// name it. Each open object remembers its keys; each open array counts its elements.
class PathTracker {
 public:
  explicit PathTracker(std::string file) : file_(std::move(file)) {}

  bool event(nlohmann::json::parse_event_t e, const nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    switch (e) {
      case E::object_start:
        frames_.push_back({false, {}, {}, 0});
        break;
      case E::array_start:
        frames_.push_back({true, {}, {}, 0});
        break;
      case E::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second)
          throw UserError(file_, path(), "duplicate key \"" + f.key + "\" (each key may appear once in an object)");
        break;
      }
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        element_done();
        break;
      case E::value:
        element_done();
        break;
    }
    return true;
  }

  // The JSON path of the value being parsed: "/camera/fov_deg", "/objects/1/center/2".
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) p += "/" + (f.array ? std::to_string(f.index) : f.key);
    return p;
  }

 private:
  struct Frame {
    bool array;
    std::string key;
    std::set<std::string> keys;
    size_t index;
  };
  void element_done() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  std::string file_;
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  check_json_nesting(text, file);  // before nlohmann's parser, whose recursion a deep file would overflow
  PathTracker tracker(file);
  try {
    return nlohmann::json::parse(
        text, [&tracker](int, nlohmann::json::parse_event_t e, nlohmann::json& parsed) { return tracker.event(e, parsed); });
  } catch (const nlohmann::json::parse_error& e) {
    // Convert the byte offset into line:column, which is what an editor shows.
    size_t line = 1, col = 1;
    const size_t end = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    for (size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string msg = e.what();
    const auto pos = msg.find("syntax error");
    if (pos != std::string::npos) msg = msg.substr(pos);
    throw UserError(file, "line " + std::to_string(line) + ", column " + std::to_string(col), "invalid JSON: " + msg);
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: a literal such as 1e999 that overflows a double; the tracker knows whose it is.
    std::string msg = e.what(), literal;
    const auto q = msg.find('\'');
    if (e.id == 406 && q != std::string::npos) literal = msg.substr(q + 1, msg.rfind('\'') - q - 1);
    if (!literal.empty())
      throw UserError(file, tracker.path().empty() ? "/" : tracker.path(),
                      "number out of range: " + literal + "; " + kNumberRange);
    const auto pos = msg.find(']');
    if (pos != std::string::npos) msg = msg.substr(pos + 2);
    throw UserError(file, tracker.path().empty() ? "/" : tracker.path(), "invalid JSON: " + msg);
  }
}

JsonObject::JsonObject(const nlohmann::json& j, std::string file, std::string path)
    : j_(&j), file_(std::move(file)), path_(std::move(path)) {
  if (!j.is_object()) throw UserError(file_, path_.empty() ? "/" : path_, "expected an object, found " + type_name(j));
}

JsonValue JsonObject::at(const std::string& key) {
  if (!j_->contains(key)) throw UserError(file_, path_ + "/" + key, "required key is missing");
  used_.insert(key);
  return JsonValue((*j_)[key], file_, path_ + "/" + key);
}

std::optional<JsonValue> JsonObject::get(const std::string& key) {
  if (!j_->contains(key)) return std::nullopt;
  used_.insert(key);
  return JsonValue((*j_)[key], file_, path_ + "/" + key);
}

float JsonObject::number(const std::string& key, float fallback) {
  auto v = get(key);
  return v ? v->number() : fallback;
}
float JsonObject::number(const std::string& key) { return at(key).number(); }
int JsonObject::integer(const std::string& key, int fallback) {
  auto v = get(key);
  return v ? v->integer() : fallback;
}
bool JsonObject::boolean(const std::string& key, bool fallback) {
  auto v = get(key);
  return v ? v->boolean() : fallback;
}
std::string JsonObject::string(const std::string& key, const std::string& fallback) {
  auto v = get(key);
  return v ? v->string() : fallback;
}
std::string JsonObject::string(const std::string& key) { return at(key).string(); }
Vec3f JsonObject::vec3(const std::string& key, const Vec3f& fallback) {
  auto v = get(key);
  return v ? v->vec3() : fallback;
}
Vec3f JsonObject::vec3(const std::string& key) { return at(key).vec3(); }
Color JsonObject::color(const std::string& key, const Color& fallback) {
  auto v = get(key);
  return v ? v->color() : fallback;
}

void JsonObject::finish() const {
  for (auto it = j_->begin(); it != j_->end(); ++it) {
    if (!used_.count(it.key())) {
      std::string allowed;
      for (const auto& k : used_) allowed += (allowed.empty() ? "" : ", ") + k;
      throw UserError(file_, path_ + "/" + it.key(),
                      "unknown key \"" + it.key() + "\"" +
                          (allowed.empty() ? std::string() : " (keys read here: " + allowed + ")") +
                          "; see docs/scene-format.md");
    }
  }
}

void JsonObject::fail(const std::string& key, const std::string& what) const {
  throw UserError(file_, key.empty() ? (path_.empty() ? "/" : path_) : path_ + "/" + key, what);
}

float JsonValue::number() const {
  if (!j_->is_number()) fail("expected a number, found " + type_name(*j_));
  const double d = j_->get<double>();
  if (!std::isfinite(d) || std::abs(d) > kMaxNumber) fail("number out of range: " + found(*j_) + "; " + kNumberRange);
  return static_cast<float>(d);
}
float JsonValue::positive() const {
  const float v = number();
  if (!(v > 0.0f)) fail("must be > 0, found " + std::to_string(v));
  return v;
}
float JsonValue::non_negative() const {
  const float v = number();
  if (!(v >= 0.0f)) fail("must be >= 0, found " + std::to_string(v));
  return v;
}
int JsonValue::integer() const {
  if (!j_->is_number_integer()) fail("expected an integer, found " + type_name(*j_));
  const bool fits = j_->is_number_unsigned() ? j_->get<uint64_t>() <= uint64_t(INT32_MAX)
                                             : j_->get<int64_t>() >= INT32_MIN && j_->get<int64_t>() <= INT32_MAX;
  if (!fits) fail("integer out of range: " + found(*j_) + "; valid range [-2147483648, 2147483647]");
  return static_cast<int>(j_->get<int64_t>());
}
int JsonValue::integer(int lo, int hi) const {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!j_->is_number_integer()) fail("must be an integer in " + range + ", found " + found(*j_));
  bool fits;
  if (j_->is_number_unsigned()) {
    const uint64_t u = j_->get<uint64_t>();
    fits = hi >= 0 && u <= uint64_t(hi) && (lo <= 0 || u >= uint64_t(lo));
  } else {
    const int64_t v = j_->get<int64_t>();
    fits = v >= lo && v <= hi;
  }
  if (!fits) fail("must be an integer in " + range + ", found " + found(*j_));
  return static_cast<int>(j_->get<int64_t>());
}
uint64_t JsonValue::seed() const {
  // Exactly as written: an integer literal (nlohmann keeps 0..2^64-1 as uint64); negatives,
  // fractions, exponents and anything larger arrive as other types and are refused.
  if (!j_->is_number_unsigned()) fail("seed must be an integer in " + std::string(kSeedRange) + ", found " + found(*j_));
  return j_->get<uint64_t>();
}
bool JsonValue::boolean() const {
  if (!j_->is_boolean()) fail("expected true or false, found " + type_name(*j_));
  return j_->get<bool>();
}
std::string JsonValue::string() const {
  if (!j_->is_string()) fail("expected a string, found " + type_name(*j_));
  return j_->get<std::string>();
}
std::vector<float> JsonValue::numbers() const {
  if (!j_->is_array()) fail("expected an array of numbers, found " + type_name(*j_));
  std::vector<float> out;
  for (size_t i = 0; i < j_->size(); ++i) out.push_back(JsonValue((*j_)[i], file_, path_ + "/" + std::to_string(i)).number());
  return out;
}
Vec2f JsonValue::vec2() const {
  const auto v = numbers();
  if (v.size() != 2) fail("expected 2 numbers, found " + std::to_string(v.size()));
  return Vec2f(v[0], v[1]);
}
Vec3f JsonValue::vec3() const {
  const auto v = numbers();
  if (v.size() != 3) fail("expected 3 numbers, found " + std::to_string(v.size()));
  return Vec3f(v[0], v[1], v[2]);
}
Color JsonValue::color() const {
  const Vec3f v = vec3();
  if ((v.array() < 0.0f).any()) fail("colour components must be >= 0");
  return v.array();
}
JsonObject JsonValue::object() const { return JsonObject(*j_, file_, path_); }
std::vector<JsonValue> JsonValue::array() const {
  if (!j_->is_array()) fail("expected an array, found " + type_name(*j_));
  std::vector<JsonValue> out;
  for (size_t i = 0; i < j_->size(); ++i) out.emplace_back((*j_)[i], file_, path_ + "/" + std::to_string(i));
  return out;
}

}  // namespace phellem
