#include "scene/json_strict.h"

#include <optional>
#include <set>
#include <vector>

namespace pd {

using nlohmann::json;

namespace {

// The library's DOM builder, with a stack of where the parser is: the keys
// seen in each open object and the index in each open array.
class StrictSax {
 public:
  explicit StrictSax(json& root) : dom_(root, /*allow_exceptions=*/false) {}

  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const std::string& s) {
    return value() && dom_.number_float(v, s);
  }
  bool string(std::string& v) { return value() && dom_.string(v); }
  bool binary(json::binary_t& v) { return value() && dom_.binary(v); }

  bool start_object(std::size_t n) {
    if (!value()) return false;
    frames_.push_back({true, {}, {}, -1});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    f.key = k;
    if (!f.keys.insert(k).second) {
      fail("duplicate key \"" + k + "\" in one object (JSON readers disagree on which counts)", 0,
           path(frames_.size()));
      return false;
    }
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    if (!value()) return false;
    frames_.push_back({false, {}, {}, -1});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array();
  }

  template <class Exception>
  bool parse_error(std::size_t byte, const std::string& token, const Exception& e) {
    // The value being read when the parser stopped: the next array element.
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    std::string what = e.what();
    if (e.id == 406)  // out_of_range: a number literal beyond the double range
      what = "number " + token + " is outside the double range (about ±1.8e308)";
    fail(what, byte, path(frames_.size()));
    return false;
  }

  const std::optional<JsonTextError>& error() const { return error_; }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;  ///< the current key, in an object
    long index;       ///< the current element, in an array
  };

  // Every value advances the index of the array it is in.
  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }

  std::string path(std::size_t depth) const {
    std::string p;
    for (std::size_t k = 0; k < depth; ++k) {
      const Frame& f = frames_[k];
      if (f.object)
        p += (p.empty() ? "" : ".") + f.key;
      else
        p += "[" + std::to_string(f.index) + "]";
    }
    return p;
  }

  void fail(const std::string& what, std::size_t byte, const std::string& at) {
    if (!error_) error_.emplace(what, byte, at);
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Frame> frames_;
  std::optional<JsonTextError> error_;
};

}  // namespace

json parse_json_strict(const char* begin, const char* end) {
  json doc;
  StrictSax sax(doc);
  const bool ok = json::sax_parse(begin, end, &sax);
  if (sax.error()) throw *sax.error();
  if (!ok) throw JsonTextError("unreadable JSON", 0, "");
  return doc;
}

}  // namespace pd
