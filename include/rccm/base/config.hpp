// The run configuration as plain structs, one per section of the config file
// (io/config_reader reads them from libconfig, with every range check, in one place).
//
// Units (docs/MODEL.md): mm, N, MPa (= N/mm^2), s. Plane problems are per unit thickness
// (1 mm), so a nodal force is in N and an interface stiffness C in MPa/mm.
// The schema is documented in README.md ("Configuration reference").
#pragma once

#include "rccm/base/time_function.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace rccm {

/// A named set of mesh nodes selected by a box [xmin, xmax, ymin, ymax] (mm).
struct NodeSetDef {
  std::string name;
  std::vector<double> box;  // [xmin, xmax, ymin, ymax] (every z), or [..., zmin, zmax] in 3D
};

enum class ElementType { T3, Q4, H8 };
enum class Hypothesis { PlaneStrain, PlaneStress, Axisymmetric };

/// Every point of a mesh lies within this distance of 0, mm (the built-in mesh's origin and
/// size, a mesh file's nodes): beyond, its assembly squares past round-off and overflow.
constexpr double mesh_reach = 1e15;

/// The mesh source: a gmsh file (`file` set; 3D when it has a Physical Volume), the built-in
/// structured rectangle, or the built-in box of H8 cells (`nz` > 0: 3D).
struct MeshParams {
  std::string file;                        // a .msh (MSH 2.2 or 4.1) or .geo file, relative to the config; empty: the rectangle
  int refine = 0;                          // file: uniform refinements (each splits every cell in 4, in 8 in 3D)
  std::map<std::string, double> parameters;  // .geo: values of its DefineConstant[ name = {..., Name "name"} ]
  std::string contents;                    // file: a hash of its text (the fingerprint covers the mesh, not its name)
  std::array<double, 3> origin{0.0, 0.0, 0.0};  // mm: the rectangle's or box's lower corner, the centre of `rotation`
  std::array<double, 2> size{};            // mm
  int nx = 0, ny = 0;                      // cells along x and y
  double depth = 0.0;                      // box: its extent along z from origin's z, mm (size's third number)
  int nz = 0;                              // box: cells along z; 0: a 2D mesh
  ElementType element = ElementType::T3;
  int dimension = 2;                       // 3: the box, or a file with Physical Volumes
  int dim() const { return dimension; }
  double rotation = 0.0;                   // degrees, counter-clockwise about `axis` through `origin`
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // unit; 2D: z (a turn in the plane)
  std::vector<NodeSetDef> node_sets;       // extra sets beside the edges and corners (or the file's groups)
};

/// Linear elasticity of one body (docs/MODEL.md s1): isotropic (E, nu) or orthotropic with
/// material axes 1, 2 in the x-y plane (axis 1 at `angle` from x) and 3 along z (the hoop
/// direction of an axisymmetric body); in 3D axis 3 along any direction `axis3` (a ply's
/// normal), axes 1, 2 turned by `angle` about it (material.cpp: material_axes).
struct MaterialParams {
  std::string path = "material";  // its section in the config, for messages
  bool orthotropic = false;
  double E = 0.0;   // Young's modulus, MPa
  double nu = 0.0;  // Poisson's ratio, in (-1, 0.5)
  double E1 = 0.0, E2 = 0.0, E3 = 0.0;        // MPa
  double nu12 = 0.0, nu13 = 0.0, nu23 = 0.0;  // nu_ij = -strain_j / strain_i under stress along i
  double G12 = 0.0;                           // in-plane shear modulus, MPa
  double G13 = 0.0, G23 = 0.0;                // out-of-plane shear moduli, MPa (3D; 0: not given)
  double angle = 0.0;                         // degrees, axis 1 from x (3D: from the reference axis), about axis3
  std::array<double, 3> axis3{0.0, 0.0, 1.0};  // 3D: material axis 3, unit (2D: z)
  Hypothesis hypothesis = Hypothesis::PlaneStrain;
};

/// A body of the mesh (a physical surface of a gmsh file) and its material; `name` empty:
/// every cell (the config's single `material` section).
struct BodyParams {
  std::string name;
  MaterialParams material;
};

/// What the contact nodes of an interface face (docs/MODEL.md s2).
enum class Facing { Line, Circle, Body };

/// An interface obeying the RCCM law (docs/MODEL.md s2-3): a node set facing a rigid line, a
/// rigid circle, or the node set of another body.
struct InterfaceParams {
  std::string path = "interface";          // its section in the config, for messages
  std::string boundary;                    // node set of the contact nodes (body A)
  Facing facing = Facing::Line;
  std::array<double, 3> normal{0.0, 1.0, 0.0};  // line (3D: plane): its normal, into the body (unit)
  std::array<double, 3> centre{};          // circle (3D: sphere): centre, mm (global frame)
  std::array<double, 3> axis{};            // 3D circle: a cylinder's unit axis through the centre; zero: a sphere
  double radius = 0.0;                     // circle: radius, mm
  bool inside = true;                      // circle: the body lies inside it (a hole), or outside (a cylinder)
  std::string opposite;                    // body: node set of body B along the interface
  double tolerance = 0.0;                  // body: largest distance of matched nodes, mm; 0: 1e-3 of the shortest edge
  std::string precrack;                    // node set whose contact nodes start at beta0 = 0; empty: none
  double Cn = 0.0, Ct = 0.0;               // initial stiffnesses, MPa/mm
  double w = 0.0;                          // adhesion energy threshold, mJ/mm^2 = N/mm
  double alpha = 1.0;                      // viscosity, N s/mm
  double mu = 0.0;                         // Coulomb coefficient
  std::vector<double> beta0{1.0};          // one value, or one per contact node
  std::vector<double> g0{0.0};             // initial gap, mm: one value, or one per contact node (line)
};

enum class LoadKind { Displacement, Force, Traction, Pressure };

/// A load on one component of a node set, scaled in time by `amplitude`.
/// Displacement: mm per node; Force: N per node (axisymmetric: on the whole ring);
/// Traction: MPa along the set's edges; Pressure: MPa normal to them, pushing into the body
/// (no component).
struct LoadParams {
  std::string path;  // "loads.[k]", for messages
  std::string node_set;
  LoadKind kind = LoadKind::Displacement;
  int component = 0;  // 0 = x, 1 = y, 2 = z (3D)
  TimeFunction amplitude;
};

struct TimeParams {
  double T = 0.0;   // final time, s
  int steps = 210;  // steps of the fixed-step integrators (the paper's 210 increments)
};

enum class ContactMethod { Bipotential, Rccm, Newton };
enum class SweepForm { GaussSeidel, Jacobi };
enum class RhoRule { Eigen, Paper };
/// The sparse solver of the body's stiffness K0 (la/spd_solver.hpp): CHOLMOD (embedded, one
/// process), PETSc with MUMPS (direct, distributed), PETSc CG with GAMG (iterative);
/// auto: CHOLMOD in one process, MUMPS under mpirun with several (la/spd_solver.hpp,
/// chosen_linear_solver; the config reader reads a solver section's "auto" as the one it
/// stands for in the run).
enum class LinearSolver { Auto, Cholmod, Mumps, CgGamg };

struct LinearSolverParams {
  LinearSolver kind = LinearSolver::Auto;
  double tolerance = 1e-12;  // cg-gamg: relative residual of each solve
  bool out_of_core = false;  // mumps: the factor written to disk (MUMPS_OOC_TMPDIR, else /tmp)
};

/// Numerics of the contact solve at fixed beta (docs/MODEL.md s5, docs/SOLVERS.md).
struct SolverParams {
  ContactMethod method = ContactMethod::Bipotential;  // the paper's, the classical RCCM one, or semi-smooth Newton
  double over_relaxation = 1.5;  // rccm: the projected Gauss-Seidel's relaxation factor, in (0, 2)
  double tolerance = 1e-10;      // relative change of Rbar and scaled natural-map residual
  int max_iterations = 2000;     // sweeps per contact solve
  int local_iterations = 100;    // predictor-corrector steps per node and sweep (Gauss-Seidel)
  SweepForm form = SweepForm::GaussSeidel;
  int anderson = 5;              // bipotential Gauss-Seidel: sweeps combined by Anderson acceleration (0: plain sweeps)
  int block_sweeps = 1;          // bipotential Gauss-Seidel: each block of neighbouring pairs updated this many times per sweep (default: 3D 2)
  RhoRule rho = RhoRule::Eigen;  // eigen: 1/lambda_max of the node block; paper: eq. 34
  double relaxation = 1.0;       // Jacobi under-relaxation of the update, in (0, 1]
  bool active_set = true;        // the exact step: solve the linear problem of a status pattern (default: 2D only)
  int active_set_max_nodes = 4096;  // beyond, on a dense W0: sweeps only (the exact step keeps two dense (2n)^2 matrices: 32 n^2 bytes)
  int compressed_min_nodes = 512;   // from this many contact pairs on, W0 is compressed (HODLR) from sparse solves, never dense, and the exact step mixes its matrix from it (bipotential, newton)
  bool springs_follow_beta = false;  // W0's springs follow beta where they lag it (default: 3D only; docs/MODEL.md s4)
  LinearSolverParams linear;        // the body's K0 solves (setup: W0, load responses; body state at output)
  /// Whether the contact solver works on a compressed W0 (bipotential, newton): where
  /// compressed_min_nodes applies.
  bool reads_compressed_W0() const { return method == ContactMethod::Bipotential || method == ContactMethod::Newton; }
};

/// How beta evolves: integrated by ARKODE or explicit Euler, the rate-independent limit,
/// or held at beta0 (contact steps only).
enum class Method { Arkode, Euler, RateIndependent, ContactOnly };
enum class ArkodeScheme { Dirk, Erk };

/// Time integration of beta (docs/MODEL.md s6).
struct IntegratorParams {
  Method method = Method::Arkode;
  ArkodeScheme scheme = ArkodeScheme::Dirk;  // arkode: implicit DIRK (robust as alpha -> 0) or ERK
  std::string table;                          // arkode Butcher table name; empty: the scheme's default
  /// The DIRK scheme's default table (ARK4(3)6L's ESDIRK: docs/PERFORMANCE.md).
  static constexpr const char* default_dirk_table = "ARKODE_ARK436L2SA_DIRK_6_3_4";
  double rtol = 1e-6, atol = 1e-10;           // arkode tolerances (beta is dimensionless)
  double max_step = 0.0;                      // s; 0: T / 50 (largest_step)
  double initial_step = 0.0;                  // s; 0: ARKODE's estimate
  double fixed_step = 0.0;                    // s; > 0: no error control (order studies); 0: adaptive
  double min_step = 0.0;                      // s; 0: 1e-9 T (a smaller step fails the run)
  int max_steps = 200000;                     // accepted steps per output interval
  double fixed_point_tolerance = 1e-10;       // rate-independent: change of beta
  int fixed_point_iterations = 500;
  /// The largest step ARKODE may take over [0, T]: max_step, or T / 50 by default.
  double largest_step(double T) const { return max_step > 0 ? max_step : T / 50; }
};

/// A named point, in the mesh source's frame (mm): a watched point of the interface (the
/// nearest contact pair) or a probe of a body (the nearest mesh node).
struct NamedPoint {
  std::string name;
  std::array<double, 3> point{};  // z = 0 in 2D
};

struct OutputParams {
  std::string directory = "results";
  std::vector<double> times;      // s, in [0, T]
  std::vector<NamedPoint> watch;  // interface points: beta, u, Radh, Rbar at every step
  std::vector<NamedPoint> probes; // body points: displacement at every step
  int checkpoint_steps = 100;     // a restart point every this many accepted steps; 0: only at a stop
  int every = 0;                  // a ParaView frame every this many accepted steps too; 0: output times only
};

struct Config {
  /// The hypothesis of the bodies (one for all of them, checked on reading).
  Hypothesis hypothesis() const { return bodies.front().material.hypothesis; }

  std::string file;                  // path it was read from
  std::map<std::string, int> lines;  // line of each setting in the file ("interface.g0"), 0 for --set
  /// How a setting given outside the file came, where it was not a --set the user typed:
  /// output.directory from "-o", "--restart DIR" or a sweep's case directory.
  std::map<std::string, std::string> origins;
  /// Fingerprint of every parsed value that defines the problem and its time grid (all but
  /// output.directory, checkpoint_steps, every, and the numerical controls a failure message
  /// asks to change; fingerprint()): a checkpoint restarts only a run of the same settings,
  /// however they are written (order, 69000 or 6.9e4, line ends, defaults spelled out).
  std::string settings;
  std::string fingerprint() const;  // a new field goes in there unless it is such a control
  /// The same values, one digest per setting name ("interface.alpha=1f2e3d4c time.T=..."): a
  /// restart refused for other settings names them (differing_settings).
  std::string settings_parts;
  std::string fingerprint_parts() const;
  /// A hash of those numerical controls alone (report.json: a resumed sweep says which of its
  /// complete cases ran with other controls than the sweep gives now).
  std::string controls_fingerprint() const;

  /// "file:line: path" for messages about a setting found wrong after reading (a list of
  /// the wrong length once the mesh is known, an unwritable directory); "--set path" for one
  /// given on the command line, or its origin ("-o") where it has one.
  std::string where(const std::string& path) const;

  MeshParams mesh;
  std::vector<BodyParams> bodies;           // `material` (one, for every cell) or `bodies`
  std::vector<InterfaceParams> interfaces;  // `interface` (one) or `interfaces`
  std::vector<LoadParams> loads;
  TimeParams time;
  SolverParams solver;
  IntegratorParams integrator;
  OutputParams output;
};

/// The config name of a method ("arkode", "euler", "rate-independent", "contact-only").
const char* method_name(Method m);

/// Whether alpha = 0 on every interface: the rate-independent limit (docs/MODEL.md s3).
bool alpha_zero_everywhere(const Config& cfg);

/// The method that runs in place of `m` when alpha = 0 on every interface: rate-independent for
/// the viscous methods (they need alpha > 0), contact-only as it is (it holds beta at beta0).
Method rate_independent_limit(Method m);

/// The config name of a contact method ("bipotential", "rccm", "newton").
const char* contact_method_name(ContactMethod m);

/// A note for each setting the config writes that the run's methods do not read (e.g.
/// integrator.rtol with the "euler" integrator, solver.anderson with the "newton" solver),
/// naming where it is written and which method reads it. time.steps is not noted: the shipped
/// configs keep it for `rccm compare`'s fixed-step integrators beside ARKODE.
std::vector<std::string> unused_settings(const Config& cfg);

/// The names whose digests differ between two Config::settings_parts, as a phrase
/// ("interface.alpha differs", "interface.alpha, time.T differ"); empty when either is empty (a
/// checkpoint or report of an earlier version).
std::string differing_settings(const std::string& parts, const std::string& other);

/// The config name of a hypothesis ("plane_strain", "plane_stress", "axisymmetric").
const char* hypothesis_name(Hypothesis h);

}  // namespace rccm
