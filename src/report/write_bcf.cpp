// --bcf FILE: BCF 3.0 (buildingSMART's BIM Collaboration Format) for issue
// trackers and BIM/CAD viewers: a zip of bcf.version, extensions.xml and one
// folder per topic (bcf_topics.h) with its markup.bcf and one viewpoint.bcfv
// (a perspective camera on the finding, its parts selected by AuthoringToolId).
// The same input gives the same bytes: GUIDs from fingerprints, a fixed date,
// a fixed zip layout (zip_archive.h). docs/report-format.md, "BCF".
#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "report/bcf_topics.h"
#include "report/bcf_view.h"
#include "report/export_finding.h"
#include "report/finding_text.h"
#include "report/markup_escape.h"
#include "report/writer.h"
#include "scene/units.h"
#include "zip_archive.h"

namespace pd {

namespace {

/// A report has no date of its own and an export must not carry the run's
/// time (equal input, equal bytes): every topic is dated the zip epoch. Its
/// GUID, not its date, tells a tracker whether it has seen the topic before.
const char* const kCreationDate = "1980-01-01T00:00:00Z";
const char* const kAuthor = "pdcheck";
const char* const kColourA = "3B82F6";  // the HTML page's part A (blue) and part B (amber)
const char* const kColourB = "F59E0B";

// The specification's sample bcf.version, its element closed at once: the
// sample holds a line break that its own version.xsd refuses as content.
const char* const kVersion =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Version VersionId=\"3.0\" "
    "xsi:noNamespaceSchemaLocation=\"https://raw.githubusercontent.com/buildingSMART/BCF-XML/"
    "release_3_0/Schemas/version.xsd\"\n"
    "    xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"/>\n";

const char* topic_type(Status s) {
  switch (s) {
    case Status::kInterference:
      return "Interference";
    case Status::kClearanceViolation:
      return "Clearance violation";
    case Status::kFalsePositive:
      return "False positive";
    case Status::kUndecided:
      return "Undecided";
    case Status::kError:
      return "Not checked";
    case Status::kSeparated:
      break;
  }
  return "Separated";
}
const Status kTopicStatuses[] = {Status::kInterference, Status::kClearanceViolation,
                                 Status::kFalsePositive, Status::kUndecided, Status::kError};

std::string esc(const std::string& s) {
  return markup_escape(s);
}

/// A number as the JSON report writes it (its shortest round trip; also a valid xs:double).
std::string num(double x) {
  return nlohmann::json(x).dump();
}

std::string xyz(const char* element, const Vec3& v, const std::string& indent) {
  return indent + "<" + element + ">\n" + indent + "  <X>" + num(v.x()) + "</X>\n" + indent +
         "  <Y>" + num(v.y()) + "</Y>\n" + indent + "  <Z>" + num(v.z()) + "</Z>\n" + indent +
         "</" + element + ">\n";
}

std::string extensions_xml() {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Extensions>\n  <TopicTypes>\n";
  for (const Status s : kTopicStatuses)
    x += "    <TopicType>" + esc(topic_type(s)) + "</TopicType>\n";
  x += "  </TopicTypes>\n  <TopicStatuses>\n    <TopicStatus>Open</TopicStatus>\n"
       "    <TopicStatus>Closed</TopicStatus>\n  </TopicStatuses>\n  <TopicLabels>\n";
  for (const Status s : kTopicStatuses)
    x += "    <TopicLabel>" + std::string(status_name(s)) + "</TopicLabel>\n";
  for (const BaselineState b :
       {BaselineState::kNew, BaselineState::kUnchanged, BaselineState::kUpdated})
    x += "    <TopicLabel>" + std::string(baseline_state_name(b)) + "</TopicLabel>\n";
  x += "    <TopicLabel>suppressed</TopicLabel>\n  </TopicLabels>\n</Extensions>\n";
  return x;
}

std::string title(const ExportFinding& f, const std::string& units, size_t members) {
  std::string t = f.a + " / " + f.b + ": " + status_name(f.pair->status);
  if (f.pair->duplicate) t += ", duplicate (placed twice)";
  // A decided depth only: an undecided pair's is a lower bound (its bracket is in the description).
  if (f.depth &&
      (f.pair->status == Status::kInterference || f.pair->status == Status::kFalsePositive))
    t += ", " + depth_meaning(f.pair->depth_source) + " " + short_number(*f.depth) + " " + units;
  if (members > 1) t += " (and " + std::to_string(members - 1) + " more)";
  return t;
}

/// Open unless every finding of the topic is suppressed: accepted by review.
bool closed(const std::vector<ExportFinding>& fs) {
  for (const ExportFinding& f : fs)
    if (f.suppression.empty()) return false;
  return true;
}

std::string markup_xml(const std::string& guid, const std::string& viewpoint_guid,
                       const std::vector<ExportFinding>& fs, const std::string& units) {
  const ExportFinding& f = fs.front();
  std::set<std::string> labels;  // sorted, once each
  std::string description;
  for (const ExportFinding& m : fs) {
    labels.insert(status_name(m.pair->status));
    if (m.pair->duplicate) labels.insert("duplicate");
    if (!m.baseline_state.empty()) labels.insert(m.baseline_state);
    if (!m.suppression.empty()) labels.insert("suppressed");
    description += (description.empty() ? "" : "\n") + m.message + " [fingerprint " +
                   m.fingerprint + (m.group.empty() ? "" : ", group " + m.group) + "]";
  }
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Markup>\n";
  x += "  <Topic Guid=\"" + guid + "\" TopicType=\"" + esc(topic_type(f.pair->status)) +
       "\" TopicStatus=\"" + (closed(fs) ? "Closed" : "Open") + "\">\n";
  x += "    <Title>" + esc(title(f, units, fs.size())) + "</Title>\n    <Labels>\n";
  for (const std::string& l : labels) x += "      <Label>" + esc(l) + "</Label>\n";
  x += "    </Labels>\n";
  x += std::string("    <CreationDate>") + kCreationDate + "</CreationDate>\n";
  x += std::string("    <CreationAuthor>") + kAuthor + "</CreationAuthor>\n";
  x += "    <Description>" + esc(description) + "</Description>\n";
  x += "    <Viewpoints>\n      <ViewPoint Guid=\"" + viewpoint_guid +
       "\">\n        <Viewpoint>viewpoint.bcfv</Viewpoint>\n      </ViewPoint>\n"
       "    </Viewpoints>\n  </Topic>\n</Markup>\n";
  return x;
}

std::string component(const std::string& id, const std::string& indent) {
  return indent + "<Component>\n" + indent + "  <OriginatingSystem>" + kAuthor +
         "</OriginatingSystem>\n" + indent + "  <AuthoringToolId>" + esc(id) +
         "</AuthoringToolId>\n" + indent + "</Component>\n";
}

std::optional<Aabb> box_of(const Part& p) {
  if (p.error) return std::nullopt;
  return p.box;
}

std::string visinfo_xml(const std::string& viewpoint_guid, const std::vector<ExportFinding>& fs,
                        const RunResult& run, double to_metres) {
  const ExportFinding& f = fs.front();
  const PairResult& r = *f.pair;
  std::vector<std::string> ids;  // the topic's parts, each once, in order of appearance
  for (const ExportFinding& m : fs)
    for (const std::string* id : {&m.a, &m.b})
      if (std::find(ids.begin(), ids.end(), *id) == ids.end()) ids.push_back(*id);
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<VisualizationInfo Guid=\"" +
                  viewpoint_guid + "\">\n  <Components>\n    <Selection>\n";
  for (const std::string& id : ids) x += component(id, "      ");
  x += "    </Selection>\n    <Visibility DefaultVisibility=\"true\"/>\n    <Coloring>\n";
  for (const auto& [colour, id] : {std::pair{kColourA, &f.a}, std::pair{kColourB, &f.b}})
    x += std::string("      <Color Color=\"") + colour + "\">\n        <Components>\n" +
         component(*id, "          ") + "        </Components>\n      </Color>\n";
  x += "    </Coloring>\n  </Components>\n";

  const ViewTarget target = view_target(f.at, box_of(run.parts[r.a]), box_of(run.parts[r.b]));
  const PerspectiveCamera c = camera_on(target, r.direction);
  x += "  <PerspectiveCamera>\n" + xyz("CameraViewPoint", c.viewpoint * to_metres, "    ") +
       xyz("CameraDirection", c.direction, "    ") + xyz("CameraUpVector", c.up, "    ") +
       "    <FieldOfView>" + num(c.field_of_view) + "</FieldOfView>\n    <AspectRatio>" +
       num(c.aspect_ratio) + "</AspectRatio>\n  </PerspectiveCamera>\n";
  // The depth as a line from where it was found: only where the report says where.
  if (target.at && f.depth && *f.depth > 0.0) {
    const Vec3 start = target.centre * to_metres;
    const Vec3 end = (target.centre + *f.depth * r.direction) * to_metres;
    x += "  <Lines>\n    <Line>\n" + xyz("StartPoint", start, "      ") +
         xyz("EndPoint", end, "      ") + "    </Line>\n  </Lines>\n";
  }
  x += "</VisualizationInfo>\n";
  return x;
}

}  // namespace

std::string render_bcf(const ReportInput& in) {
  // BCF lengths are metres; the scene's unit is checked when it is read.
  const double to_metres = unit_in_mm(in.context.units).value_or(1.0) / 1000.0;
  std::vector<ZipEntry> entries = {{"bcf.version", kVersion}, {"extensions.xml", extensions_xml()}};
  for (const BcfTopic& t : bcf_topics(in)) {
    std::vector<ExportFinding> fs;
    for (const size_t k : t.pairs) fs.push_back(export_finding(in, k));
    const std::string guid = bcf_guid("topic", t.key);
    const std::string viewpoint = bcf_guid("viewpoint", t.key);
    entries.push_back({guid + "/", ""});
    entries.push_back({guid + "/markup.bcf", markup_xml(guid, viewpoint, fs, in.context.units)});
    entries.push_back({guid + "/viewpoint.bcfv", visinfo_xml(viewpoint, fs, in.run, to_metres)});
  }
  return zip_archive(entries);
}

}  // namespace pd
