#include "say.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <sstream>

#include "printable.h"
#include "report/review_text.h"
#include "scene/scene.h"

void say(const char* level, const std::string& message) {
  std::cerr << "pdcheck: " << level << ": " << pd::printable(message) << "\n";
}

void say_review(const pd::ReportInput& report) {
  std::istringstream review_text(pd::review_lines(report));
  for (std::string line; std::getline(review_text, line);) std::cerr << pd::printable(line) << "\n";
}

int jobs_or_all_cores(int jobs) {
  return jobs > 0 ? jobs : static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
}

pd::ScenePartsLoader scene_parts_loader(int jobs, double load_timeout) {
  return [jobs, load_timeout](const std::string& scene, const std::optional<std::string>& units,
                              std::optional<double> tolerance) {
    return pd::load_scene_parts(scene, units, tolerance, jobs, load_timeout);
  };
}
