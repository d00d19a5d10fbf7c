#include "brep/brep_file.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <UnitsMethods.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>

#include "brep/quiet_stdout.h"
#include "brep/shape_mesh.h"

namespace pd {

bool is_brep_path(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == "step" || ext == "stp" || ext == "brep";
}

const char* sag_basis_name(SagBasis b) {
  return b == SagBasis::kBound ? "bound" : "estimate";
}

Tessellation combine(const Tessellation& a, const Tessellation& b) {
  Tessellation out = a;
  out.deflection = std::max(a.deflection, b.deflection);
  out.sag = std::max(a.sag, b.sag);
  out.basis = a.basis == SagBasis::kBound && b.basis == SagBasis::kBound ? SagBasis::kBound
                                                                        : SagBasis::kEstimate;
  out.faces = a.faces + b.faces;
  out.free_form = a.free_form + b.free_form;
  out.tolerance = std::max(a.tolerance, b.tolerance);
  return out;
}

namespace {

std::string name_of(const TDF_Label& label) {
  Handle(TDataStd_Name) n;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), n)) return "";
  return TCollection_AsciiString(n->Get()).ToCString();
}

std::string extension_of(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Open CASCADE reports through its default messenger, whose printer writes to
// standard output, where pdcheck writes its report: the printers go, once per
// process.
void silence_messages() {
  static const bool done = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    return true;
  }();
  (void)done;
}

// A product's shape placed by the assembly, and the products already meshed.
struct Reader {
  double deflection;
  BrepFile out;
  std::map<std::string, ShapeMesh> meshed;  // by the product label's entry

  const ShapeMesh& mesh_of(const TDF_Label& product, const TopoDS_Shape& shape) {
    TCollection_AsciiString entry;
    TDF_Tool::Entry(product, entry);
    auto it = meshed.find(entry.ToCString());
    if (it == meshed.end())
      it = meshed.emplace(entry.ToCString(), mesh_solids(shape, deflection)).first;
    return it->second;
  }

  void add_leaf(int node, const std::string& path_name, const ShapeMesh& m, const gp_Trsf& place) {
    BrepLeaf leaf;
    leaf.solids = m.solids;
    leaf.tessellation = m.tessellation;
    const double scale = std::abs(place.ScaleFactor());
    leaf.tessellation.sag *= scale;
    leaf.tessellation.deflection = deflection;
    leaf.mesh.triangles = m.mesh.triangles;
    leaf.mesh.vertices.resize(3, m.mesh.vertices.cols());
    for (long k = 0; k < m.mesh.vertices.cols(); ++k) {
      gp_XYZ p(m.mesh.vertices(0, k), m.mesh.vertices(1, k), m.mesh.vertices(2, k));
      place.Transforms(p);
      leaf.mesh.vertices.col(k) = Vec3(p.X(), p.Y(), p.Z());
    }
    if (m.solids == 0)
      leaf.error = "\"" + path_name + "\" holds no solid (a surface model: shells or faces " +
                   "only); pdcheck checks solids";
    else if (m.open_edges > 0)
      out.warnings.push_back("\"" + path_name + "\": its mesh has " +
                             std::to_string(m.open_edges) +
                             " open edges (a solid whose faces do not close)");
    out.nodes[size_t(node)].leaf = int(out.leaves.size());
    out.leaves.push_back(std::move(leaf));
  }

  int add_node(const std::string& name, int parent) {
    out.nodes.push_back({name, parent, -1});
    return int(out.nodes.size()) - 1;
  }

  // `label` is a product (an assembly or a part) placed by `place`, its node `node`.
  void walk(const TDF_Label& label, const gp_Trsf& place, int node, const std::string& path_name) {
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
      TDF_LabelSequence components;
      XCAFDoc_ShapeTool::GetComponents(label, components, false);
      for (int k = 1; k <= components.Length(); ++k) {
        const TDF_Label& c = components.Value(k);
        TDF_Label product;
        if (!XCAFDoc_ShapeTool::GetReferredShape(c, product)) continue;
        std::string name = name_of(c);
        if (name.empty()) name = name_of(product);
        const gp_Trsf local = XCAFDoc_ShapeTool::GetLocation(c).Transformation();
        const int child = add_node(name, node);
        walk(product, place.Multiplied(local), child, path_name + "/" + name);
      }
      return;
    }
    add_leaf(node, path_name, mesh_of(label, XCAFDoc_ShapeTool::GetShape(label)), place);
  }
};

BrepFile read_step(const std::string& path, double deflection) {
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("BinXCAF", doc);
  // The reader converts the file's unit to the document's.
  XCAFDoc_DocumentTool::SetLengthUnit(doc, 1.0, UnitsMethods_LengthUnit_Millimeter);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  reader.SetColorMode(false);
  reader.SetLayerMode(false);
  {
    QuietStdout quiet;  // a reader's own prints, past the messenger
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw std::runtime_error("not a STEP file Open CASCADE can read");
    if (!reader.Transfer(doc)) throw std::runtime_error("Open CASCADE could not transfer its shapes");
  }
  Reader r{deflection, {}, {}};
  r.out.unit = "mm";
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  shapes->GetFreeShapes(roots);
  for (int k = 1; k <= roots.Length(); ++k) {
    const TDF_Label& root = roots.Value(k);
    const std::string name = name_of(root);
    const int node = r.add_node(name, -1);
    r.walk(root, XCAFDoc_ShapeTool::GetLocation(root).Transformation(), node, name);
  }
  XCAFApp_Application::GetApplication()->Close(doc);
  if (r.out.leaves.empty()) throw std::runtime_error("holds no shape");
  return std::move(r.out);
}

BrepFile read_occt_brep(const std::string& path, double deflection) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  {
    QuietStdout quiet;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw std::runtime_error("not a BRep file Open CASCADE can read");
  }
  BrepFile out;
  std::string name = path.substr(path.find_last_of('/') + 1);
  name = name.substr(0, name.find_last_of('.'));
  out.nodes.push_back({name, -1, 0});
  const ShapeMesh m = mesh_solids(shape, deflection);
  BrepLeaf leaf;
  leaf.mesh = m.mesh;
  leaf.tessellation = m.tessellation;
  leaf.solids = m.solids;
  if (m.solids == 0)
    leaf.error = "\"" + name + "\" holds no solid (a surface model: shells or faces only); " +
                 "pdcheck checks solids";
  out.leaves.push_back(std::move(leaf));
  return out;
}

}  // namespace

BrepFile read_brep_file(const std::string& path, double deflection) {
  silence_messages();
  if (::access(path.c_str(), R_OK) != 0)
    throw std::runtime_error("B-rep file " + path + ": cannot be read");
  try {
    BrepFile f = extension_of(path) == "brep" ? read_occt_brep(path, deflection)
                                              : read_step(path, deflection);
    for (std::string& w : f.warnings) w = "B-rep file " + path + ": " + w;
    for (BrepLeaf& l : f.leaves)
      if (l.error) l.error = "B-rep file " + path + ": " + *l.error;
    return f;
  } catch (const Standard_Failure& e) {
    throw std::runtime_error("B-rep file " + path + ": Open CASCADE failed: " +
                             e.GetMessageString());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("B-rep file " + path + ": " + e.what());
  }
}

}  // namespace pd
