#include "scene/json_reader.h"

#include <cmath>

namespace phellem {

namespace {
std::string type_name(const nlohmann::json& j) { return j.type_name(); }
}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  try {
    return nlohmann::json::parse(text);
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
    throw UserError(file, "line " + std::to_string(line) + ", column " + std::to_string(col),
                    "invalid JSON: " + msg);
  } catch (const nlohmann::json::exception& e) {
    // e.g. out_of_range 406: a literal such as 1e999 that overflows to infinity.
    std::string msg = e.what();
    const auto pos = msg.find(']');
    if (pos != std::string::npos) msg = msg.substr(pos + 2);
    throw UserError(file, "", "invalid JSON: " + msg + " (numbers must be finite)");
  }
}

JsonObject::JsonObject(const nlohmann::json& j, std::string file, std::string path)
    : j_(&j), file_(std::move(file)), path_(std::move(path)) {
  if (!j.is_object())
    throw UserError(file_, path_.empty() ? "/" : path_, "expected an object, found " + type_name(j));
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
  throw UserError(file_, key.empty() ? path_ : path_ + "/" + key, what);
}

float JsonValue::number() const {
  if (!j_->is_number()) fail("expected a number, found " + type_name(*j_));
  const double d = j_->get<double>();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail("number is not finite");
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
  const auto v = j_->get<int64_t>();
  if (v < -(1LL << 31) || v > (1LL << 31) - 1) fail("integer out of range");
  return static_cast<int>(v);
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
  for (size_t i = 0; i < j_->size(); ++i)
    out.push_back(JsonValue((*j_)[i], file_, path_ + "/" + std::to_string(i)).number());
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
  for (size_t i = 0; i < j_->size(); ++i)
    out.emplace_back((*j_)[i], file_, path_ + "/" + std::to_string(i));
  return out;
}

}  // namespace phellem
