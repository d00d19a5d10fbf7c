#include "results/codec.h"

#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "results/fingerprint.h"
#include "results/pair_fields.h"
#include "results/part_fields.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

StopReason stop_reason_from_name(const std::string& name) {
  for (StopReason r : {StopReason::kNone, StopReason::kProvenSeparated, StopReason::kContact,
                       StopReason::kEpaCertificate, StopReason::kCertificate, StopReason::kBayesian,
                       StopReason::kCap, StopReason::kAboveTolerance})
    if (name == stop_reason_name(r)) return r;
  throw std::invalid_argument("unknown stop_reason \"" + name + "\"");
}

// The complete encoding stores an enum's value; one outside the enum is refused,
// never cast into it.
template <class E>
E enum_from_value(const json& j, E last, const char* what) {
  const int v = j.get<int>();
  if (v < 0 || v > static_cast<int>(last))
    throw std::runtime_error(std::string("unknown ") + what + " " + std::to_string(v));
  return static_cast<E>(v);
}

template <class T>
bool is_empty(const T& v) {
  if constexpr (std::is_same_v<T, bool>)
    return !v;
  else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::vector<std::string>>)
    return v.empty();
  else if constexpr (std::is_same_v<T, std::vector<std::pair<double, double>>>)
    return v.empty();
  else
    return false;
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

// Writes each field (a visitor of for_each_field) into `out`.
struct Writer {
  Encoding encoding;
  json& out;

  template <class T>
  void operator()(const Field& f, const T& v) const {
    const bool report = encoding == Encoding::kReport;
    if (report ? !f.shown || (f.omit_empty && is_empty(v)) : f.echo) return;
    if constexpr (IsOptional<T>::value) {
      if (!v) return;
    }
    if (!f.group)
      out[f.key] = value(v);
    else if (!f.echo || out.contains(f.group))
      out[f.group][f.key] = value(v);
  }

  json value(double v) const { return v; }
  json value(int v) const { return v; }
  json value(long v) const { return v; }
  json value(bool v) const { return v; }
  json value(const std::string& v) const { return v; }
  json value(const std::vector<std::string>& v) const { return v; }
  json value(const std::vector<std::pair<double, double>>& v) const { return v; }
  template <class T>
  json value(const std::array<T, 2>& v) const {
    return {v[0], v[1]};
  }
  json value(const Vec3& v) const {
    if (encoding == Encoding::kComplete) return {v.x(), v.y(), v.z()};
    return {v.x() + 0.0, v.y() + 0.0, v.z() + 0.0};  // the report writes no −0
  }
  json value(Status s) const {
    if (encoding == Encoding::kComplete) return static_cast<int>(s);
    return status_name(s);
  }
  json value(StopReason s) const {
    if (encoding == Encoding::kComplete) return static_cast<int>(s);
    return stop_reason_name(s);
  }
  template <class T>
  json value(const std::optional<T>& v) const {
    return value(*v);
  }
  json value(ExactVerdict v) const {
    if (encoding == Encoding::kComplete) return static_cast<int>(v);
    return exact_verdict_name(v);
  }
  json value(ExactBasis b) const {
    if (encoding == Encoding::kComplete) return static_cast<int>(b);
    return exact_basis_name(b);
  }
  json value(const SolveStats& s) const { return nested(s); }
  json value(const MotionTrace& m) const { return nested(m); }
  json value(const ExactCheck& e) const { return nested(e); }

  template <class T>
  json nested(const T& v) const {
    json j = json::object();
    for_each_field(v, Writer{encoding, j});
    return j;
  }
};

// Reads each field (a visitor of for_each_field) from `in`: a field the
// encoding has must be there, an optional or omitted one may be absent.
struct Reader {
  Encoding encoding;
  const json& in;

  template <class T>
  void operator()(const Field& f, T& v) const {
    const bool report = encoding == Encoding::kReport;
    if (f.echo || (report && !f.shown)) return;
    if (IsOptional<T>::value || (report && f.omit_empty)) {
      const json* object = &in;
      if (f.group) {
        const auto group = in.find(f.group);
        object = group == in.end() ? nullptr : &*group;
      }
      const auto it = object ? object->find(f.key) : in.end();
      if (!object || it == object->end()) {
        v = T{};
        return;
      }
      read(*it, v);
    } else {
      read((f.group ? in.at(f.group) : in).at(f.key), v);
    }
  }

  void read(const json& j, double& v) const { v = j.get<double>(); }
  void read(const json& j, int& v) const { v = j.get<int>(); }
  void read(const json& j, long& v) const { v = j.get<long>(); }
  void read(const json& j, bool& v) const { v = j.get<bool>(); }
  void read(const json& j, std::string& v) const { v = j.get<std::string>(); }
  void read(const json& j, std::vector<std::string>& v) const {
    v = j.get<std::vector<std::string>>();
  }
  void read(const json& j, std::vector<std::pair<double, double>>& v) const {
    v.clear();
    for (const json& p : j) v.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
  }
  template <class T>
  void read(const json& j, std::array<T, 2>& v) const {
    read(j.at(0), v[0]);
    read(j.at(1), v[1]);
  }
  void read(const json& j, Vec3& v) const {
    v = Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
  }
  void read(const json& j, Status& s) const {
    s = encoding == Encoding::kComplete ? enum_from_value(j, Status::kUndecided, "status")
                                        : status_from_name(j.get<std::string>());
  }
  void read(const json& j, StopReason& s) const {
    s = encoding == Encoding::kComplete
            ? enum_from_value(j, StopReason::kAboveTolerance, "stop reason")
            : stop_reason_from_name(j.get<std::string>());
  }
  template <class T>
  void read(const json& j, std::optional<T>& v) const {
    T x{};
    read(j, x);
    v = std::move(x);
  }
  void read(const json& j, ExactVerdict& v) const {
    v = encoding == Encoding::kComplete
            ? enum_from_value(j, ExactVerdict::kTimeout, "exact verdict")
            : exact_verdict_from_name(j.get<std::string>());
  }
  void read(const json& j, ExactBasis& b) const {
    b = encoding == Encoding::kComplete ? enum_from_value(j, ExactBasis::kSolids, "exact basis")
                                        : exact_basis_from_name(j.get<std::string>());
  }
  void read(const json& j, SolveStats& s) const { for_each_field(s, Reader{encoding, j}); }
  void read(const json& j, MotionTrace& m) const { for_each_field(m, Reader{encoding, j}); }
  void read(const json& j, ExactCheck& e) const { for_each_field(e, Reader{encoding, j}); }
};

}  // namespace

json pair_to_report(const PairResult& r, const std::string& id_a, const std::string& id_b) {
  json j = {{"a", id_a}, {"b", id_b}, {"fingerprint", pair_fingerprint(id_a, id_b)}};
  for_each_field(r, Writer{Encoding::kReport, j});
  return j;
}

json part_to_report(const PartResult& p) {
  json j = json::object();
  for_each_field(p, Writer{Encoding::kReport, j});
  return j;
}

PartResult part_from_report(const json& j) {
  PartResult p;
  for_each_field(p, Reader{Encoding::kReport, j});
  return p;
}

PairResult pair_from_report(const json& j, int a, int b) {
  PairResult r;
  r.a = a;
  r.b = b;
  for_each_field(r, Reader{Encoding::kReport, j});
  return r;
}

std::string encode_pair_result(const PairResult& r) {
  json j = {{"a", r.a}, {"b", r.b}};
  for_each_field(r, Writer{Encoding::kComplete, j});
  const std::vector<std::uint8_t> bytes = json::to_msgpack(j);
  return std::string(bytes.begin(), bytes.end());
}

PairResult decode_pair_result(const std::string& s) {
  const json j = json::from_msgpack(s);
  PairResult r;
  r.a = j.at("a").get<int>();
  r.b = j.at("b").get<int>();
  for_each_field(r, Reader{Encoding::kComplete, j});
  return r;
}

}  // namespace pd
