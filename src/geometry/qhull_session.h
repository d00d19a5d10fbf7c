// RAII around one reentrant qhull run (qhT is per call, so runs are independent).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace pd {

class QhullSession {
 public:
  /// Runs qhull on `dim`-dimensional points stored point after point.
  QhullSession(int dim, std::vector<double> coords, const char* options);
  ~QhullSession();
  QhullSession(const QhullSession&) = delete;
  QhullSession& operator=(const QhullSession&) = delete;

  bool ok() const { return exit_code_ == 0; }
  const std::string& error() const { return error_; }
  qhT* qh() { return &qh_; }
  /// The indices of the input points that are vertices of the hull, ascending.
  std::vector<int> vertex_ids();

 private:
  qhT qh_;
  std::vector<double> coords_;  // qhull keeps pointers into this buffer
  int exit_code_ = 0;
  std::string error_;
};

}  // namespace pd
