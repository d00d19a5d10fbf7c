#include "brep/shape_tree.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <UnitsMethods.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "brep/quiet_stdout.h"

namespace pd {

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

struct Walker {
  ShapeTree& out;

  int add_node(const std::string& name, int parent) {
    out.nodes.push_back({name, parent, -1});
    return int(out.nodes.size()) - 1;
  }

  // `label` is a product (an assembly or a part) placed by `place`, its node `node`.
  void walk(const TDF_Label& label, const gp_Trsf& place, int node, const std::string& names) {
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
      TDF_LabelSequence components;
      XCAFDoc_ShapeTool::GetComponents(label, components, false);
      for (int k = 1; k <= components.Length(); ++k) {
        const TDF_Label& c = components.Value(k);
        TDF_Label product;
        if (!XCAFDoc_ShapeTool::GetReferredShape(c, product)) continue;
        std::string name = name_of(c);  // the instance's name, else its product's
        if (name.empty()) name = name_of(product);
        const gp_Trsf local = XCAFDoc_ShapeTool::GetLocation(c).Transformation();
        walk(product, place.Multiplied(local), add_node(name, node), names + "/" + name);
      }
      return;
    }
    TCollection_AsciiString entry;
    TDF_Tool::Entry(label, entry);
    out.nodes[size_t(node)].leaf = int(out.leaves.size());
    out.leaves.push_back({XCAFDoc_ShapeTool::GetShape(label), entry.ToCString(), place, names});
  }
};

void read_step(const std::string& path, ShapeTree& out) {
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
    if (!reader.Transfer(doc))
      throw std::runtime_error("Open CASCADE could not transfer its shapes");
  }
  out.unit = "mm";
  Walker w{out};
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  shapes->GetFreeShapes(roots);
  for (int k = 1; k <= roots.Length(); ++k) {
    const TDF_Label& root = roots.Value(k);
    const std::string name = name_of(root);
    w.walk(root, XCAFDoc_ShapeTool::GetLocation(root).Transformation(), w.add_node(name, -1), name);
  }
  XCAFApp_Application::GetApplication()->Close(doc);
}

void read_occt_brep(const std::string& path, ShapeTree& out) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  {
    QuietStdout quiet;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw std::runtime_error("not a BRep file Open CASCADE can read");
  }
  std::string name = path.substr(path.find_last_of('/') + 1);
  name = name.substr(0, name.find_last_of('.'));
  out.nodes.push_back({name, -1, 0});
  out.leaves.push_back({shape, "0", gp_Trsf(), name});
}

}  // namespace

ShapeTree read_shape_tree(const std::string& path) {
  silence_messages();
  ShapeTree out;
  if (extension_of(path) == "brep")
    read_occt_brep(path, out);
  else
    read_step(path, out);
  if (out.leaves.empty()) throw std::runtime_error("holds no shape");
  return out;
}

}  // namespace pd
