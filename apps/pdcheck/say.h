// What the pdcheck commands share: messages on stderr, the job count, and the
// loader that reads a saved report's scene again.
#pragma once

#include <string>

#include "report/html_from_report.h"
#include "report/writer.h"

/// One line on stderr, "pdcheck: LEVEL: message"; input text in it (ids,
/// paths) cannot forge another line.
void say(const char* level, const std::string& message);

/// The review on stderr, one escaped line at a time (ids in it).
void say_review(const pd::ReportInput& report);

/// --jobs as given, else every core.
int jobs_or_all_cores(int jobs);

/// A saved report's scene, read again for its page's 3D views.
pd::ScenePartsLoader scene_parts_loader(int jobs, double load_timeout);
