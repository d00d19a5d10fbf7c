// Scenes with rules for the rules' tests (scene/rule_index.h, rules_json.cpp):
// inline tetrahedron parts with labels, and the SceneError a scene gives.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace pd::test {

inline pd::SceneSpec scene_with(const std::string& parts, const std::string& rules,
                                const std::string& extra = "") {
  return pd::parse_scene_json(
      R"({"tolerance": 0.05, "parts": [)" + parts + "]" + extra + R"(, "rules": )" + rules + "}",
      "s.json", "");
}

inline std::string rule_part(const std::string& id, const std::string& labels) {
  return R"({"id": ")" + id + R"(", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]])" +
         (labels.empty() ? "" : ", " + labels) + "}";
}

inline std::string scene_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace pd::test
