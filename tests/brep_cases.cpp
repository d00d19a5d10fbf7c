#include "brep_cases.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <stdexcept>

#include "brep/quiet_stdout.h"
#include "brep/shape_tree.h"

namespace pd_test {

namespace {

TopoDS_Shape make(const BrepSolid& s) {
  const auto& p = s.p;
  switch (s.kind) {
    case BrepSolid::Kind::kBox:
      return BRepPrimAPI_MakeBox(p[0], p[1], p[2]).Shape();
    case BrepSolid::Kind::kCylinder:
      return BRepPrimAPI_MakeCylinder(p[0], p[1]).Shape();
    case BrepSolid::Kind::kTorus:
      return BRepPrimAPI_MakeTorus(p[0], p[1]).Shape();
    case BrepSolid::Kind::kSphere:
      return BRepPrimAPI_MakeSphere(p[0]).Shape();
    case BrepSolid::Kind::kPlateWithHole: {
      const TopoDS_Shape plate = BRepPrimAPI_MakeBox(p[0], p[1], p[2]).Shape();
      const gp_Ax2 axis(gp_Pnt(p[0] / 2, p[1] / 2, -1.0), gp::DZ());
      const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(axis, p[3], p[2] + 2.0).Shape();
      return BRepAlgoAPI_Cut(plate, hole).Shape();
    }
    case BrepSolid::Kind::kShaftWithGroove: {
      const TopoDS_Shape shaft = BRepPrimAPI_MakeCylinder(p[0], p[1]).Shape();
      const gp_Ax2 axis(gp_Pnt(0, 0, p[3]), gp::DZ());
      const TopoDS_Shape ring = BRepPrimAPI_MakeTorus(axis, p[0], p[2]).Shape();
      return BRepAlgoAPI_Cut(shaft, ring).Shape();
    }
    case BrepSolid::Kind::kTwoBoxes: {
      TopoDS_Compound c;
      BRep_Builder b;
      b.MakeCompound(c);
      b.Add(c, BRepPrimAPI_MakeBox(p[0], p[1], p[2]).Shape());
      b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(p[0], 0, 0), p[0], p[1], p[2]).Shape());
      return c;
    }
    case BrepSolid::Kind::kBoxShell: {
      const TopoDS_Shape box = BRepPrimAPI_MakeBox(p[0], p[1], p[2]).Shape();
      TopExp_Explorer x(box, TopAbs_SHELL);
      return x.Current();
    }
    case BrepSolid::Kind::kWavySlab: {
      TColgp_Array2OfPnt grid(1, 7, 1, 7);
      for (int i = 1; i <= 7; ++i)
        for (int j = 1; j <= 7; ++j) {
          const double x = p[0] * (i - 1) / 6.0, y = p[0] * (j - 1) / 6.0;
          grid(i, j) = gp_Pnt(x, y, 0.5 * std::sin(x) * std::cos(y));
        }
      const Handle(Geom_BSplineSurface) s = GeomAPI_PointsToBSplineSurface(grid).Surface();
      const TopoDS_Face f = BRepBuilderAPI_MakeFace(s, 1e-7).Face();
      return BRepPrimAPI_MakePrism(f, gp_Vec(0, 0, p[1])).Shape();
    }
    case BrepSolid::Kind::kChamferedSquare: {
      // A cone through the square's corners cuts its four sides in hyperbolas.
      const TopoDS_Shape block =
          BRepPrimAPI_MakeBox(gp_Pnt(-p[0], -p[0], 0.0), 2 * p[0], 2 * p[0], p[1]).Shape();
      const TopoDS_Shape cone = BRepPrimAPI_MakeCone(1.5 * p[0], 1.05 * p[0], p[1]).Shape();
      return BRepAlgoAPI_Common(block, cone).Shape();
    }
    case BrepSolid::Kind::kTilted: {
      gp_Trsf a, b;
      a.SetRotation(gp::OX(), 30.0 * M_PI / 180.0);
      b.SetRotation(gp::OZ(), 20.0 * M_PI / 180.0);
      return BRepPrimAPI_MakeBox(p[0], p[1], p[2]).Shape().Moved(TopLoc_Location(b * a));
    }
  }
  throw std::logic_error("unknown solid kind");
}

gp_Trsf placement(const BrepCasePart& part) {
  gp_Trsf r, t;
  if (part.angle != 0.0)
    r.SetRotation(gp_Ax1(gp::Origin(), gp_Dir(part.axis.x(), part.axis.y(), part.axis.z())),
                  part.angle);
  t.SetTranslation(gp_Vec(part.at.x(), part.at.y(), part.at.z()));
  return t * r;
}

void write(const std::string& path, const Handle(TDocStd_Document) & doc, const std::string& unit) {
  STEPCAFControl_Controller::Init();  // registers the statics set below
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  Interface_Static::SetCVal("write.step.unit", unit == "in" ? "INCH" : "MM");
  STEPCAFControl_Writer w;
  w.SetNameMode(true);
  pd::QuietStdout quiet;
  if (!w.Transfer(doc, STEPControl_AsIs) || w.Write(path.c_str()) != IFSelect_RetDone)
    throw std::runtime_error("cannot write " + path);
}

Handle(TDocStd_Document) new_document() {
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("BinXCAF", doc);
  XCAFDoc_DocumentTool::SetLengthUnit(doc, 1.0, UnitsMethods_LengthUnit_Millimeter);
  return doc;
}

}  // namespace

void write_step_assembly(const std::string& path, const std::vector<BrepCasePart>& parts,
                         const std::string& unit) {
  Handle(TDocStd_Document) doc = new_document();
  Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label assembly = tool->NewShape();
  TDataStd_Name::Set(assembly, "assembly");
  for (const BrepCasePart& p : parts) {
    const TDF_Label product = tool->AddShape(make(p.solid), false);
    TDataStd_Name::Set(product, p.name.c_str());
    const TDF_Label instance = tool->AddComponent(assembly, product, TopLoc_Location(placement(p)));
    TDataStd_Name::Set(instance, p.name.c_str());
  }
  tool->UpdateAssemblies();
  write(path, doc, unit);
  XCAFApp_Application::GetApplication()->Close(doc);
}

void write_step_part(const std::string& path, const BrepCasePart& part, const std::string& unit) {
  Handle(TDocStd_Document) doc = new_document();
  Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label product = tool->AddShape(
      BRepBuilderAPI_Transform(make(part.solid), placement(part), true).Shape(), false);
  TDataStd_Name::Set(product, part.name.c_str());
  write(path, doc, unit);
  XCAFApp_Application::GetApplication()->Close(doc);
}

void write_brep_part(const std::string& path, const BrepCasePart& part) {
  const TopoDS_Shape s = BRepBuilderAPI_Transform(make(part.solid), placement(part), true).Shape();
  if (!BRepTools::Write(s, path.c_str())) throw std::runtime_error("cannot write " + path);
}

std::vector<Points> leaf_face_samples(const std::string& path, int n) {
  const pd::ShapeTree tree = pd::read_shape_tree(path);
  std::vector<Points> out;
  for (const pd::ShapeTree::Leaf& l : tree.leaves) {
    std::vector<Vec3> pts;
    const TopoDS_Shape placed = l.product.Moved(TopLoc_Location(l.place));
    for (TopExp_Explorer x(placed, TopAbs_FACE); x.More(); x.Next()) {
      const TopoDS_Face f = TopoDS::Face(x.Current());
      BRepAdaptor_Surface s(f);
      double u0, u1, v0, v1;
      BRepTools::UVBounds(f, u0, u1, v0, v1);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          const double u = u0 + (u1 - u0) * i / n, v = v0 + (v1 - v0) * j / n;
          BRepClass_FaceClassifier c(f, gp_Pnt2d(u, v), 1e-9);
          if (c.State() == TopAbs_OUT) continue;
          const gp_Pnt p = s.Value(u, v);
          pts.emplace_back(p.X(), p.Y(), p.Z());
        }
    }
    Points m(3, long(pts.size()));
    for (size_t k = 0; k < pts.size(); ++k) m.col(long(k)) = pts[k];
    out.push_back(std::move(m));
  }
  return out;
}

ExactReference exact_reference(const std::string& brep_a, const std::string& brep_b) {
  const auto read = [](const std::string& path) {
    TopoDS_Shape s;
    BRep_Builder b;
    if (!BRepTools::Read(s, path.c_str(), b)) throw std::runtime_error("cannot read " + path);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(s, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    return solids;
  };
  const std::vector<TopoDS_Shape> a = read(brep_a), b = read(brep_b);
  ExactReference out;
  out.distance = INFINITY;
  for (const TopoDS_Shape& sa : a)
    for (const TopoDS_Shape& sb : b) {
      BRepExtrema_DistShapeShape d(sa, sb);
      if (d.IsDone()) out.distance = std::min(out.distance, d.Value());
      BRepAlgoAPI_Common common(sa, sb);
      if (!common.IsDone()) throw std::runtime_error("Common failed");
      GProp_GProps g;
      BRepGProp::VolumeProperties(common.Shape(), g);
      out.common_volume += g.Mass();
      if (g.Mass() > 0) {
        Bnd_Box box;
        BRepBndLib::AddOptimal(common.Shape(), box, false, false);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        out.common_min_extent =
            std::max(out.common_min_extent, std::min({x1 - x0, y1 - y0, z1 - z0}));
      }
    }
  return out;
}

}  // namespace pd_test
