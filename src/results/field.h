// How one field of a result is written: the attributes its description gives
// (results/pair_fields.h), which the one codec (results/codec.h) follows in
// both of its encodings.
#pragma once

namespace pd {

/// The two encodings of a result (results/codec.h).
enum class Encoding {
  /// Every field, doubles bit for bit (MessagePack): the worker messages and the
  /// refinement cache.
  kComplete,
  /// The report's pair entry (docs/report-format.md): part ids and the pair's
  /// fingerprint, fields shown as `when` says, empty ones left out as
  /// `unless_empty` says; read back by merge and --reuse.
  kReport,
};

/// One field's key and how the report shows it. Conditions are on fields
/// described before it (a reader has read them by then).
struct Field {
  const char* key;
  /// Nested in this object (both encodings); the object is written when one of
  /// its fields is.
  const char* group = nullptr;
  /// In the report only when true (e.g. a depth only for decided pairs); the
  /// complete encoding has it always.
  bool shown = true;
  /// The report leaves it out when empty, false or absent (read back: the default).
  bool omit_empty = false;
  /// The report repeats here a field given earlier; never read, not in the
  /// complete encoding.
  bool echo = false;

  constexpr Field in(const char* object) const {
    Field f = *this;
    f.group = object;
    return f;
  }
  constexpr Field when(bool condition) const {
    Field f = *this;
    f.shown = shown && condition;
    return f;
  }
  constexpr Field unless_empty() const {
    Field f = *this;
    f.omit_empty = true;
    return f;
  }
  constexpr Field echoing() const {
    Field f = *this;
    f.echo = true;
    return f;
  }
};

}  // namespace pd
