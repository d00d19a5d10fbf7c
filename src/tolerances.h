// Every numerical tolerance of pdcheck, in one place. docs/numerics.md explains each.
//
// Unless stated otherwise a tolerance is *relative*: it is multiplied by the size
// of the object it applies to (a pair's frame scale, see geometry/frame.h). Each
// pair is solved in a frame where both parts lie in the unit ball, so inside the
// solvers these numbers are used as they are.
#pragma once

#include <cstddef>
#include <limits>

namespace pd::tol {

/// A point set whose smallest principal extent is below this fraction of its size
/// is flat (or collinear, or a point): it gets a lower-dimensional hull. At 1e-12
/// only truly flat input qualifies; a 1e-6 thin plate stays a solid.
inline constexpr double kFlat = 1e-12;

/// Overlap at or below this fraction of the pair size is contact, not
/// interference: it is the resolution of double-precision Minkowski differences
/// and facet offsets (a few hundred ulps), well below any tessellation tolerance.
inline constexpr double kTouch = 1e-11;

/// A gap (unit frame) at or below this is the rounding of evaluating h_P − h_Q
/// at a facet normal of a touching pair (a few dozen ulps of the unit frame's
/// coordinates; the normal itself is rounded too): the pair touches and its
/// depth is 0, in both the exact reference and mlsl, so the two cannot differ
/// by which side of 0 their rounding fell. Far below the 1e-12 of the pair's
/// scale every depth is held to, and below kTouch.
inline constexpr double kGapRounding = 1e-14;

/// Depths closer to the user's tolerance than this fraction of the pair size are
/// on the boundary: they are always classified as false positives (depth <= tol),
/// so a status cannot flip with rounding noise. The report gives the margin.
inline constexpr double kClassifyBand = 1e-11;

/// Ipopt's convergence tolerance (its option "tol") in the unit frame.
inline constexpr double kIpoptTol = 1e-10;
/// Ipopt's cap on iterations for one local solve.
inline constexpr int kIpoptMaxIter = 200;

/// Two local optima are the same when their directions are closer than this
/// angle (radians) on the unit sphere.
inline constexpr double kSameOptimumAngle = 1e-6;

/// A descent that ends closer than this angle to a known optimum, and no lower,
/// is in that optimum's basin: Ipopt is not called again for it.
inline constexpr double kSameBasinAngle = 1e-2;

/// The global-minimum certificate (solve/certificate.h): a cube-sphere grid of
/// 6·kCertificateGrid² cells (cell radius ~0.1 rad at 12) bounds the gap below
/// per cell; the cells left open are covered by at most kCertificateCaps caps of
/// at most kCertificateCapAngle radians, each searched exactly on a local
/// Minkowski difference of at most kNeighbourhoodPoints points, or cut into
/// smaller cells (solve/cap_subdivision.h) each searched so, at most
/// kSubdivisionCells of them. Beyond these limits the exact hull decides (and
/// the report says so).
inline constexpr int kCertificateGrid = 12;
inline constexpr double kCertificateCapAngle = 0.35;
inline constexpr int kCertificateCaps = 12;
inline constexpr long kNeighbourhoodPoints = 300;
inline constexpr long kSubdivisionCells = 4000;
/// A cap's local difference P' − Q' is searched without a hull while its facet
/// normal candidates (planes of three P' or Q' points, cross products of a P'
/// and a Q' edge) times their valuation (|P'| + |Q'| dot products) stay below
/// this: ~20 µs of work, qhull's fixed cost per call on this class of machine.
inline constexpr double kCandidateFacetWork = 20000;
/// The certificate's spherical cells (solve/certificate.cpp, cap_subdivision.cpp).
/// Geometry, not accuracy: a cell's angular radius is padded by kCellRadiusPad
/// (relative) so that rounding never leaves a corner outside its cap; two open
/// cells are one group when their centres are within kCellJoinSlack times the
/// sum of their radii; a gnomonic cell has at least kMinCellAreaFraction of the
/// mean cell area at any grid (the fail-fast count of caps); a subdivided
/// cell's candidate lists are computed for a cap kSubdivisionValidMargin times
/// its own, so that every child's cap lies inside its parent's (a corner
/// child's cap reaches just to the parent's corner).
inline constexpr double kCellRadiusPad = 1e-9;
inline constexpr double kCellJoinSlack = 1.05;
inline constexpr double kMinCellAreaFraction = 0.3;
inline constexpr double kSubdivisionValidMargin = 1.25;

/// The EPA bracket (solve/epa.h), unit frame, absolute. kEpaRounding bounds the
/// rounding of a face's lower bound min(n·a, n·b, n·c): the differences a = p − q
/// (|a| <= 2, <= 2^-53·|a| per coordinate), the three-term dot products (<= 3·2^-53
/// ·Σ|n_k a_k|) and the normalisation of n (|n| = 1 to 4·2^-53): about 20·2^-53·2
/// = 4.4e-15 together, taken as 1e-14. Each face's bound is lowered by it, and a
/// face or step is used only when the origin is inside it by more than it.
/// kEpaBracket: the bracket is certified (the answer final) when upper − lower is
/// at most this: the nearest face is a facet of P − Q to rounding, and the depth
/// reported (upper) is within it of the exact one, far below kTouch.
/// GJK (solve/gjk.h) tests "on the simplex" against kEpaRounding too: the origin
/// within it of a face still counts as held by a tetrahedron, within it of a
/// segment or triangle makes GJK complete the simplex off its span, and a point
/// beyond the simplex by no more than it leaves a supporting plane (touching).
inline constexpr double kEpaRounding = 1e-14;
inline constexpr double kEpaBracket = 2 * kEpaRounding;
/// Effort, not accuracy: GJK's support evaluations and EPA's expansions per
/// pair. Past them the bracket so far seeds MLSL, which decides as before.
inline constexpr int kGjkMaxIterations = 64;
inline constexpr int kEpaMaxIterations = 10000;
/// An EPA bracket left open no wider than this (unit frame) stopped by
/// rounding, not by a wrong turn: when MLSL's first certificate then finds no
/// cover either (minima tied in a band), the exact hull of P − Q decides at
/// once, if it has at most kExactHandoverPoints points (~1 s of qhull).
inline constexpr double kEpaNarrowBracket = 1e-12;
inline constexpr double kExactHandoverPoints = 4e6;
/// A certified EPA depth (unit frame) below this is recomputed exactly from the
/// input coordinates (solve/exact_facet.h): the bracket's width kEpaBracket and
/// the unit frame's rounding (~1e-16) are then more than 2e-10 of the depth,
/// and the exact step brings the error to one rounding of the result. Above
/// it the certified bracket alone is within 2e-10 relative.
inline constexpr double kExactFacetDepth = 1e-4;

/// A vertex counts as active at a direction v when its support value is within
/// this of the extreme value; used to read the optimal facet off a local solve.
inline constexpr double kActiveLoose = 1e-7;
inline constexpr double kActiveTight = 1e-10;
/// The active-set bands the facet snap tries at a solve's end point, loosest
/// first (solve/facet_snap.cpp); a descent's end point tries the looser bands
/// from kDescentSnapBand down before these.
inline constexpr double kSnapBands[] = {kActiveLoose, 1e-8, 1e-9, kActiveTight};

/// The loosest active-set band (unit frame) of the snap tried at a descent's end
/// point, before any Ipopt call; tighter bands follow by factors of 10.
inline constexpr double kDescentSnapBand = 1e-3;
/// The smooth descent (solve/smooth_descent.cpp), unit frame. Effort and
/// conditioning, not accuracy (its end point is only a start for the snap and
/// Ipopt): the smoothing lengths μ it descends through, the Newton steps per μ,
/// the gradient norm (times μ) it stops at, the Armijo constant and the
/// halvings of its line search, and how far (times μ) below the top a term of
/// the log-sum-exp is dropped (e^-40 ≈ 4e-18 relative).
inline constexpr double kDescentMu[] = {3e-3, 6e-4, 1.2e-4};
inline constexpr int kDescentSteps = 20;
inline constexpr double kDescentStationary = 1e-3;
inline constexpr double kDescentArmijo = 1e-4;
inline constexpr int kDescentHalvings = 30;
inline constexpr double kLogSumExpCut = 40.0;

/// The facet snap accepts a plane when its normal fits the active vertices to
/// this residual (smallest singular value of the active edge matrix).
inline constexpr double kSnapResidual = 1e-9;
/// The snap's fitted plane is then refined to the exact facet of P − Q with its
/// normal within this angle (radians) of the fit (solve/facet_snap.cpp): a fit
/// within kSnapResidual of edges >= 1e-3 of the frame is within 1e-6 of it.
inline constexpr double kSnapCap = 1e-5;
/// Polishing a descent's end point with Ipopt (solve/local_search.cpp), unit
/// frame: the reduced problem holds the vertices within kPolishBand of the
/// extreme at the end point (every vertex active within a few degrees of it);
/// a vertex beyond the current level by more than kPolishSlack (rounding) joins
/// it; the facet snap of Ipopt's answer is taken only when no higher and within
/// kPolishSnapAngle (radians) of it (a wrong active set could jump elsewhere).
inline constexpr double kPolishBand = 0.05;
inline constexpr double kPolishSlack = 1e-12;
inline constexpr double kPolishSnapAngle = 1e-3;

/// --baseline: a finding of unchanged status is `updated` when its depth moved
/// by more than both kBaselineDepthAbs · tolerance and kBaselineDepthRel · the
/// old depth (docs/ci.md): solver and tessellation noise stays `unchanged`.
inline constexpr double kBaselineDepthAbs = 0.1;
inline constexpr double kBaselineDepthRel = 0.05;

/// Time box of one mesh file's convex decomposition, seconds. Past it the
/// decomposer's fallback pieces are used and the part's pairs say so.
inline constexpr double kDecomposeSeconds = 20.0;

/// Nonconvex parts (geometry/convexity.h, decompose.h). Absolute, not relative:
/// the concavity tolerance is this fraction of the scene's tolerance (scene
/// units). A part is convex, and a piece accepted, when its hull lies within it
/// of the part; two hull excesses at a contact add up, so at 0.25 an exact fit
/// scores at most half the tolerance and stays a false positive.
inline constexpr double kConcavityFraction = 0.25;

/// A part's transform is rigid when its singular values are within this of 1
/// (absolute): a rotation written with 6 decimals (0.707107) passes, a scale
/// (a units mistake, almost always) gets a warning with its factors.
inline constexpr double kRigidPlacement = 1e-5;
/// Numerical care, not accuracy: a placement whose largest and smallest
/// stretch factors differ by at most this fraction stretches every length
/// alike (a rotation, the units), so a file's convexity may be measured on its
/// placed mesh and divided by the stretch (scene/parts.cpp): the two differ by
/// rounding only. Anything else is measured in file coordinates.
inline constexpr double kSimilarPlacement = 1e-12;

/// The units check (scene/setup_warnings.h, docs/numerics.md "Units"): a
/// part's size (largest box extent) against the median of the other parts'.
/// Within kUnitsLikeFactor of 25.4, 1000 or 304.8 times it (or 1/that), with
/// two or more other parts, and kUnitsLikeGap times beyond every other part's
/// size: the factor of inches, metres or feet against millimetres. At least
/// kUnitsLikeFar times it (or 1/that): no ordinary assembly's part. A glTF
/// part read in the metres its format declares, at least kUnitsLikeFormat
/// times it: written in millimetres. A part kUnitsLikeGap times beyond every
/// other part's size that meets no other part's box, where a units factor
/// brings its size within the others' range (kUnitsLikeRange slack) and its
/// box among theirs.
inline constexpr double kUnitsLikeFactor = 0.03;
/// Two parts are at the same place (a duplicate, batch/pair_solve.h) when
/// their placed hulls' vertices agree within this fraction of the part's size
/// plus four coordinate steps: far below any placement a designer means, far
/// above the rounding of one placement written twice.
inline constexpr double kSamePlace = 1e-9;
inline constexpr double kUnitsLikeFar = 100.0;
inline constexpr double kUnitsLikeFormat = 20.0;
inline constexpr double kUnitsLikeGap = 10.0;
inline constexpr double kUnitsLikeRange = 2.0;
/// Limits of one decomposition (beyond them: not complete, pairs unconfirmed),
/// and the samples of a piece's concavity estimate (a fifth of them to rank
/// candidate cuts).
inline constexpr int kDecomposeMaxPieces = 256;
inline constexpr int kDecomposeMaxDepth = 24;
inline constexpr int kDecomposeSamples = 1000;
/// Work budget of one decomposition: concavity estimates (one per cell and per
/// tried merge, ~1-5 ms each). Deterministic, unlike the time box.
inline constexpr long kDecomposeMaxWork = 4000;
/// Samples of the coarse screen run before a piece's full estimate: a cell it
/// finds more than twice the tolerance concave is cut without the full one.
/// The convexity screen of a whole part (geometry/convexity.h) runs one first
/// too: a part it finds nonconvex needs no face polygons built.
inline constexpr int kDecomposeScreenSamples = 64;
/// Effort, not accuracy: the candidate cuts of one piece are drawn from at most
/// kDecomposeCutPlanes planes of concave faces and kDecomposeCutEdges reflex
/// edges (paired into planes through two of them), and scored on at most
/// kDecomposeCutFaces concave faces (evenly thinned beyond). Among cuts of
/// equal concavity the balanced one wins: the volume imbalance weighs
/// kDecomposeBalance times the piece's concavity. The root cells lie
/// kDecomposeRootPad (relative to the mesh's diagonal) outside it, so that no
/// face lies in a root plane.
inline constexpr int kDecomposeCutPlanes = 64;
inline constexpr int kDecomposeCutEdges = 24;
inline constexpr int kDecomposeCutFaces = 256;
inline constexpr double kDecomposeBalance = 1e-3;
inline constexpr double kDecomposeRootPad = 1e-6;
/// A point is on a hull's facet when within kOnHull of its plane, relative to
/// the point set's size (geometry/convexity.cpp): the rounding of a facet's
/// offset, as kTouch is for a pair.
inline constexpr double kOnHull = 1e-12;
/// A mesh's coordinate noise (geometry/convexity.h, coordinate_noise): at least
/// kNoiseFloor of its size, and kNoiseUlps steps of float32 (2^-24) at its
/// largest coordinate, as mesh files store them.
inline constexpr double kNoiseFloor = 1e-9;
inline constexpr double kNoiseUlps = 8.0;
/// The side of a closed mesh a point is on is read off its nearest face only
/// when the nearest point lies inside that face by more than this in each
/// barycentric coordinate (geometry/mesh_intersect.cpp); nearer an edge or
/// vertex the ray test decides.
inline constexpr double kNearestFaceMargin = 1e-6;
/// An ASCII PLY coordinate assimp read (with its own fast_atof, not correctly
/// rounded) agrees with the file's when within this of it, relative (scene/
/// ply_check.cpp): a few float32 steps (2^-23 ≈ 1.2e-7) pass, a misreading
/// (a digit lost or shifted) is off by far more.
inline constexpr double kPlyAsciiAgreement = 1e-5;

/// Overlap thickness of a nonconvex pair (solve/overlap_thickness.h). Effort,
/// not accuracy: the bracket stays certified whatever they are, and a pair whose
/// bracket still straddles the tolerance when they run out is `undecided`.
/// Distance evaluations (one per part and cell centre or ascent step, ~2-10 us
/// each) per pair, and as many boxes (a child settled by its parent's models
/// costs none): deterministic, so the result is the same for every --jobs.
inline constexpr long kThicknessMaxEvaluations = 400000;
/// The wall-clock box per pair, seconds: the users' safety net, never reached on
/// the benchmark assemblies (their slowest pair stays far below it).
inline constexpr double kThicknessSeconds = 20.0;
/// The overlap thickness's resolution, in float32 steps of each part (the
/// spacing at its largest coordinate, as mesh files store them): a thickness
/// certified at or below kContactSteps × (step_a + step_b) cannot be told from
/// two touching surfaces' rounding (each vertex is within half a step per axis
/// of where it belongs, and each plane model's slack is about a step), so the
/// pair is touching (`separated`). A pair whose search finds no overlap above
/// it narrows its bracket until it does or until the upper end is at it,
/// whatever the tolerance (docs/solver.md, "Overlap thickness").
inline constexpr double kContactSteps = 2.0;
/// Once an interference is certified (lower bound > tolerance), the search goes
/// on until the bracket's upper end is within this fraction of its lower end,
/// so the reported depth means something (bounded by the same budget).
inline constexpr double kThicknessBracket = 0.25;
/// ... and with at most as many more distance evaluations as deciding took, or
/// this many when that was fewer: tightening a decided pair's bracket must not
/// cost more than deciding it (a union of shells' lower bound may never reach
/// the ratio above).
inline constexpr long kThicknessBracketMinEvaluations = 5000;
/// A B-rep pair's thin overlap is narrowed for the deflection bound (its
/// bracket's upper end below the tolerance less twice the sag) only when that
/// asks for no less than this fraction of its upper end. Effort, not
/// accuracy: beyond it the search costs more than the exact stage (an
/// O-ring's contact: 0.016 to 0.011 took 2,600 evaluations; a bolt's 0.0085
/// to 0.0005, 20,000).
inline constexpr double kBoundNarrowing = 0.25;
/// A box's plane models look at the faces within this multiple of the bound
/// that settles it (the best point found, or half the tolerance) of the box,
/// and bound min(sd, margin) (geometry/solid_distance.h, local_planes).
/// Effort, not accuracy: a model is sound at any margin, and a bound at or
/// above the margin is dropped. A smaller margin sees fewer faces, but its
/// bound must come below it; on the CAD assemblies (bench_cad_assemblies.py)
/// 2 took the least time per pair, 1.25, 1.5, 3 and 4 more.
inline constexpr double kThicknessModelMargin = 2.0;
/// Effort, not accuracy: the most points one surface is sampled at for the
/// deepest-surface-point bound (geometry/solid_distance.h). Any sample is a
/// sound lower bound; more only find a deeper one. The deepest pieces are
/// followed first, so a part pushed deep is found within a few hundred; a long
/// seated contact (a pin in its bore) would take tens of thousands to sample
/// at the spacing and finds nothing there that decides.
inline constexpr long kSurfaceDepthSamples = 2000;
/// ... and as a guard between two solids whose overlap thickness is bracketed
/// (batch/refine.cpp): only a point deeper than the tolerance decides there
/// (a thin part pushed deep), and the deepest pieces come first, so a quarter
/// of the budget; on the CAD assemblies it took a fifth of a refined pair's
/// time at 2000 (bench_cad_assemblies.py).
inline constexpr long kSurfaceDepthGuardSamples = 500;

/// Numerical care, not accuracy: how far taking a point or a box corner into
/// an orthonormal frame (a part's face axes) may move it, per unit of its
/// largest coordinate, with room to spare (a few roundings of a 3 × 3 product
/// and of the frame's own orthonormality). The searches that prune in a part's
/// own axes widen every box by it (docs/numerics.md, "Frames for searching");
/// their answers are computed on the coordinates as given.
inline constexpr double kFrameRounding = 32 * std::numeric_limits<double>::epsilon();
/// Local plane models (geometry/solid_distance.h). Effort, not accuracy: at
/// most this many faces near a cell, hole planes (the nearest supporting planes
/// kept: each bounds on its own), and LPs per cell (one per choice of each
/// part's active hole plane); beyond them the cell is split and the Lipschitz
/// bound holds. And the largest kappa = 1/cos(spread of a hole's normals)
/// accepted: 2, a spread <= 60 degrees (a shaft's shoulder, a 90-degree inner
/// corner, has sqrt 2); a larger kappa would only loosen the bound. 40 hole
/// planes let a whole small bore within the margin (a 6 mm bore of 72 facets
/// seen from a 1.3 mm box) be one hole: on the CAD hinge's pin pair, 16 split
/// its boxes down to 0.6 mm (9,987 boxes against 5,251).
inline constexpr int kLocalPlanesMaxFaces = 512;
inline constexpr int kLocalPlanesMaxPlanes = 40;
inline constexpr int kLocalPlanesMaxChoices = 80;
inline constexpr double kLocalPlanesMaxKappa = 2.0;
/// Where a hole's normals spread wider than kLocalPlanesMaxKappa allows (a
/// small hole wholly within the margin), its feet move along the mean of the
/// normals within 45 degrees (cos 0.7) of the plane the box's centre lies
/// deepest behind; the planes outside the spread must then stay behind every
/// foot (checked).
inline constexpr double kLocalPlanesFacingCos = 0.7;
/// Wedges (LocalPlanes::wedges) kept per part and box, and pairs of face planes
/// tried for them, nearest to the box first: each kept wedge doubles the plane
/// bound's alternatives, and two already pin a shoulder's corner down.
inline constexpr int kLocalPlanesMaxWedges = 2;
inline constexpr int kLocalPlanesWedgeTries = 8;

/// HTML report (report/write_html.h): the most triangles one part, piece or
/// overlap is shown with (larger ones decimated: report/html_geometry.h), and
/// the most the whole page holds (later findings then get no 3D view). Display
/// only: they bound the page's size and load time (docs/report-format.md).
inline constexpr size_t kHtmlPartTriangles = 4000;
inline constexpr size_t kHtmlPageTriangles = 300000;
/// The most parts of the rest of the assembly a finding's view shows around
/// its pair (as faint boxes, the nearest first).
inline constexpr size_t kHtmlContextParts = 24;
/// The most inside tests one finding's drawn overlap of nonconvex parts may
/// cost (report/html_geometry.h, solid_overlap_web_mesh): a few tenths of a
/// second; past it the view shows the finding's `at` and its thickness alone.
inline constexpr long kHtmlOverlapProbes = 200000;
/// BCF viewpoints (--bcf, report/bcf_view.h): the perspective camera's vertical
/// field of view (degrees; it just holds the finding's ball) and the aspect
/// ratio it is written with (a 16:9 screen). Display only.
inline constexpr double kBcfFieldOfView = 60.0;
inline constexpr double kBcfAspectRatio = 16.0 / 9.0;
/// A camera direction (or up vector) whose part across the depth (or the
/// view) is below this fraction of it is too near it: the next candidate is used.
inline constexpr double kBcfAcross = 0.1;

/// Where a finding is (geometry/depth_witness.h): the points of a convex set
/// within this fraction of the pair's size of its support plane along the
/// depth direction form the face the witness patch is taken on. The witness is
/// a place to look, not a measure: wide enough that a face or edge is found
/// whole when the direction is off by up to 5e-5 rad (an edge–edge optimum's
/// direction is known only to about the square root of the objective's
/// accuracy, √kIpoptTol = 1e-5); on a finely tessellated curved surface it
/// takes the few vertices around the true support point.
inline constexpr double kWitnessFace = 1e-4;

/// Finding groups (report/finding_groups.h): two findings that share a part
/// and need a fix are one group when the moves of that part that clear them
/// (each finding's direction, oriented as a move of the part) are at most this
/// angle apart (absolute, radians). Within 30° a move along one clears the
/// other's overlap with at most 1/cos 30° = 1.155 times its depth.
inline constexpr double kGroupMoveAngle = 0.5235987755982988;  // 30°

/// Sharding (batch/shard.h). A shard's plan box of a part (its placed vertices'
/// box) is widened by this fraction of its largest coordinate, so it contains the
/// hull's box whatever rounding the hull's placement took; wider boxes only add
/// planned pairs that the shard's exact test drops.
inline constexpr double kPlanBoxSlack = 1e-9;
/// Expected cost of one pair, as vertices: kShardPairCost + the two parts'
/// vertex counts (a pair's fixed work, then support evaluations linear in size).
inline constexpr double kShardPairCost = 200.0;
/// Effort, not accuracy: an inline part with at least this many vertices has
/// its hull cached (scene/hull_cache.h, one file per part and placement). A
/// smaller one is hulled in every run (≈ 0.5 ms at 100 vertices): its entry
/// would cost a 4 KB file per part, per placement, for every part of every
/// scene, with no eviction.
inline constexpr long kInlineHullCacheVertices = 1000;

/// Bytes a part's distances (SolidDistance: its mesh, trees and shells) hold
/// per triangle, as their cache counts them against the memory budget
/// (batch/part_solids.h): the resident growth of building them, measured
/// on CAD meshes (a union of shells holds up to twice as much; rounded up).
inline constexpr long kSolidBytesPerTriangle = 400;

/// Tessellation sag (geometry/tessellation_sag.h). Absolute angle, radians: an
/// edge whose facets turn by at most this is a tessellation crease inside a
/// smooth region; a sharper one is a design edge (a box's 90° edge). 50° reads
/// an 8-segment cylinder (45° creases) as tessellated; an octagonal prism is
/// read so too (declare its part's `sag` when that is wrong).
inline constexpr double kSagCreaseAngle = 0.8726646259971648;  // 50°
/// A corner normal more than acos(this) from its facet's normal (a cone's apex,
/// whose normal the mesh does not define) gives no patch estimate for the
/// facet: its crease estimate stands alone.
inline constexpr double kSagPatchMinCos = 0.5;
/// Relative: a facet's width across a tessellation crease, in its crease sag
/// (c/2)·tan(θ/4), is at most this many times its neighbour's across the same
/// edge. A large flat facet (a wall) meeting a round's first facet turns by half
/// the round's segment angle; read as a chord of that curvature with its whole
/// width it would be a sag of millimetres (a 67 mm wall beside an 8-segment
/// quarter round: 0.82 mm, for a true sag of 0.024). A uniform tessellation's
/// neighbours are within 2× (cylinders, spheres, tori, cones: equal).
inline constexpr double kSagChordRatio = 2.0;
/// `tolerance: auto` (docs/numerics.md): a pair's band is the concave sags and
/// coordinate steps of its two parts where they meet, times 1 + this. Relative:
/// it covers the measurement's error (within 10 % on generated cylinders,
/// spheres, tori and cones) and facets a little coarser than the region's
/// measured worst.
inline constexpr double kAutoToleranceMargin = 0.25;
/// A sag feature is kept as patches: its facets bucketed in a grid of this many
/// cells along its box's longest side (geometry/tessellation_sag.h, SagPatch),
/// so that "the sag near a point" reads the surface there, not every feature
/// whose box (a ring's box holds its axis) holds the point. 8: a bore's ring
/// falls into ~25 patches, each an eighth of its diameter across.
inline constexpr int kSagPatchCells = 8;

/// B-rep parts (STEP, .brep) are meshed at this fraction of the tolerance as
/// their linear deflection, unless the part or the scene gives one. A contact
/// of curved faces leaves a mesh overlap up to the concave side's sag s ≤ δ;
/// with the sags bounds, a mesh bracket [lo, hi] holds for the solids widened
/// by 2δ (docs/solver.md, "B-rep parts"), so a contact is certified a false
/// positive by the bound alone when hi + 2δ ≤ tolerance: at δ = tol/4, about
/// 3δ ≤ tol with a quarter of the tolerance to spare for the bracket's width.
inline constexpr double kDeflectionFraction = 0.25;
/// Effort, not accuracy: a triangle of a B-rep face whose coarse sag bound
/// would raise its face's sag is measured at the corners of this many cuts a
/// side ((n + 1)(n + 2)/2 surface points), the remainder the coarse bound over
/// n²: 4 gives 15 points and a sixteenth, within a quarter of the true error
/// where the coarse bound can be twice it (geometry/interpolation_bound.h).
inline constexpr int kSagRefineCuts = 4;
/// Under tolerance auto, a B-rep part without a given deflection is meshed at
/// this deflection in mm (its band then follows from the sags that gives):
/// a 10 mm radius comes out in about 70 segments.
inline constexpr double kAutoDeflectionMm = 0.01;

/// Two exact solids closer than this fraction of the pair's size (or than
/// kExactTouchMm, Open CASCADE's confusion tolerance) touch: the rounding of
/// its distances, far below any tolerance.
inline constexpr double kExactTouch = 1e-9;
inline constexpr double kExactTouchMm = 1e-7;
/// The time box of one pair's measurements on the exact solids (seconds; the
/// pair timeout, when smaller, wins). Booleans on near-coincident free-form
/// faces have taken 25 s; the Boolean stops at the box and the mesh verdict
/// stands, with the reason.
inline constexpr double kExactSeconds = 10.0;
/// The share of that box the search for a point deep inside both solids (the
/// thickness's lower bound) may use before the Boolean runs.
inline constexpr double kExactLowerShare = 0.3;
/// Effort: the exact distance of two solids measures face pairs nearest box
/// first; past this many, faces whose boxes are apart bound the distance from
/// below instead (a certified "apart by at least"). Face distances on free-form
/// faces cost up to 0.1 s each: a 375-face frame against a 337-face part took
/// 33 s to measure exactly at 70 mm apart.
inline constexpr long kExactFacePairs = 16;

}  // namespace pd::tol
