// A strict RFC 4180 reader for the CSV export's tests (--csv).
#pragma once

#include <string>
#include <vector>

namespace pd::test {

using CsvRows = std::vector<std::vector<std::string>>;

/// Every record ends in CRLF, a field is quoted or holds no comma, quote, CR
/// or LF, quotes inside a quoted field are doubled. Sets `error` on anything
/// else.
inline CsvRows parse_csv(const std::string& text, std::string& error) {
  CsvRows rows;
  std::vector<std::string> row;
  std::string f;
  size_t k = 0;
  while (k < text.size()) {
    if (text[k] == '"') {
      for (++k;; ++k) {
        if (k >= text.size()) {
          error = "unterminated quoted field";
          return rows;
        }
        if (text[k] == '"') {
          if (k + 1 < text.size() && text[k + 1] == '"') {
            f += '"';
            ++k;
          } else {
            ++k;
            break;
          }
        } else {
          f += text[k];
        }
      }
    } else {
      while (k < text.size() && text[k] != ',' && text[k] != '\r') {
        if (text[k] == '"' || text[k] == '\n') {
          error = "bare quote or LF at byte " + std::to_string(k);
          return rows;
        }
        f += text[k++];
      }
    }
    row.push_back(std::move(f));
    f.clear();
    if (k < text.size() && text[k] == ',') {
      ++k;
    } else if (text.compare(k, 2, "\r\n") == 0) {
      k += 2;
      rows.push_back(std::move(row));
      row.clear();
    } else {
      error = "a record not ended by CRLF at byte " + std::to_string(k);
      return rows;
    }
  }
  if (!row.empty()) error = "the last record has no CRLF";
  return rows;
}

}  // namespace pd::test
