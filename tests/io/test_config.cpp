// The config loader: every bad file of tests/bad/ is refused with the message its first
// line expects ("# expect: ..."), which names the line and the setting.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/model/model.hpp"
#include "rccm/io/output_directory.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <unistd.h>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

const char* good = R"(
mesh = { size = [10.0, 5.0]; nx = 4; ny = 2; };
material = { E = 1000; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y";
            table = ( (0.0, 0.0), (0.5, 0.2), (1.0, 0.1) ); } );
time = { T = 1.0; steps = 4; };
)";

}  // namespace

TEST_CASE("every bad config is refused with file, line and setting", "[config]") {
  int count = 0;
  // tests/bad: the first corpus; tests/hostile: inputs of a hostile user (issue 15).
  for (const char* corpus : {"bad", "hostile"})
  for (const auto& entry : fs::directory_iterator(fs::path(RCCM_SOURCE_DIR) / "tests" / corpus)) {
    if (entry.path().extension() != ".cfg") continue;
    std::ifstream in(entry.path());
    std::string first;
    std::getline(in, first);
    REQUIRE(first.rfind("# expect: ", 0) == 0);
    const std::string expect = first.substr(10);
    INFO(entry.path().filename().string());
    const auto build = [&]() {  // what `rccm run` does before writing anything
      const Config c = load_config(entry.path().string());
      check_output_directory(c, false);
      const Model model = test::make_model(c);
    };
    CHECK_THROWS_AS(build(), InputError);
    CHECK_THROWS_WITH(build(), Catch::Contains(expect) && Catch::Contains(entry.path().string()));
    ++count;
  }
  CHECK(count >= 65);
}

TEST_CASE("integers convert to numbers and tables are piecewise linear", "[config]") {
  const Config c = test::config_from_text(good);
  CHECK(c.bodies.at(0).material.E == 1000.0);  // written as an integer
  const TimeFunction& f = c.loads[0].amplitude;
  CHECK(f(0.25) == Approx(0.1));
  CHECK(f(0.75) == Approx(0.15));
  CHECK(f(2.0) == Approx(0.1));  // held after the last point
}

TEST_CASE("overrides (--set) change any setting, and their errors name them", "[config]") {
  const Config c = test::config_from_text(good, {"interface.mu=0.5", "solver.form=jacobi", "output.times=[0.5, 0.25]"});
  CHECK(c.interfaces[0].mu == 0.5);
  CHECK(c.solver.form == SweepForm::Jacobi);  // a bare word is a string
  CHECK(test::config_from_text(good, {"solver.rho=\"paper\""}).solver.rho == RhoRule::Paper);
  REQUIRE(c.output.times.size() == 2);
  CHECK(c.output.times[0] == 0.25);
  CHECK_THROWS_WITH(test::config_from_text(good, {"interface.mu=-1"}),
                    Catch::Contains("--set interface.mu: must be >= 0 (got -1)"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"interface.Cm=3"}),
                    Catch::Contains("--set interface.Cm: unknown setting; did you mean 'Cn'?"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"interface.mu"}), Catch::Contains("expected path=value"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"interface.mu=[1,"}), Catch::Contains("cannot parse"));
  // A list element by its index.
  CHECK(test::config_from_text(good, {"loads.[0].node_set=top"}).loads[0].node_set == "top");
  CHECK_THROWS_WITH(test::config_from_text(good, {"loads.[7].value=1"}), Catch::Contains("numbered from 0"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"loads.value=1"}), Catch::Contains("e.g. loads.[0].value"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"time.[0].T=1"}), Catch::Contains("not one"));
  // Found wrong once the mesh is known: named as the --set that gave it, not as the file.
  CHECK_THROWS_WITH(test::make_model(test::config_from_text(good, {"loads.[0].node_set=\"nowhere\""})),
                    Catch::StartsWith("--set loads.[0].node_set: no node set named 'nowhere'"));
  // A value of the right kind over one of the wrong kind in the file: the file's line is named
  // (the next run without the override would stop on it); integers and reals are one kind.
  CHECK(test::config_from_text(good, {"time.T=2"}).time.T == 2.0);
  CHECK(test::config_from_text(good, {"interface.w=1"}).interfaces[0].w == 1.0);
  const std::string wrong_directory = std::string(good) + "output = { directory = 5; };\n";
  CHECK_THROWS_WITH(test::config_from_text(wrong_directory, {"output.directory=\"results\""}),
                    Catch::Contains(":8: output.directory: must be a string (got an integer); --set or -o replaces it"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"solver.form=5"}),
                    Catch::Contains("--set solver.form: must be a string (got an integer)"));  // no such setting in the file
  // A value of the right kind that the file's read refuses, under an override: the same (the
  // empty directory ran under -o though refused without it).
  const std::string empty_directory = std::string(good) + "output = { directory = \"\"; };\n";
  CHECK_THROWS_WITH(test::config_from_text(empty_directory, {"output.directory=\"results\""}),
                    Catch::EndsWith(":8: output.directory: must not be empty; --set or -o replaces it in this run, but "
                                    "the file's value is wrong: mend it"));
  CHECK_THROWS_WITH(test::config_from_text(good, {"mesh.nx=0"}), Catch::Contains("--set mesh.nx: must be >= 1"));
  const std::string zero_cells = std::regex_replace(std::string(good), std::regex("nx = 4"), "nx = 0");
  CHECK_THROWS_WITH(test::config_from_text(zero_cells, {"mesh.nx=4"}),
                    Catch::EndsWith(":2: mesh.nx: must be >= 1 (got 0); --set or -o replaces it in this run, but the "
                                    "file's value is wrong: mend it"));
  // The file's values are read together, as the next run would: its output.times beyond the
  // shorter time.T given beside it is no fault of the file.
  const std::string late_times = std::string(good) + "output = { times = [0.75]; };\n";
  CHECK(test::config_from_text(late_times, {"time.T=0.5", "output.times=[0.25]"}).time.T == 0.5);
  // A refusal of the file alone at a setting no override replaces is for its own run to say:
  // output.times beyond the file's time.T, under a longer time.T.
  const std::string times_past_T = std::string(good) + "output = { times = [2.0]; };\n";
  CHECK(test::config_from_text(times_past_T, {"time.T=3"}).output.times.at(0) == 2.0);
  // A --set the user typed is named so; -o, --restart and a sweep's case directory by their origin.
  Config dir_cfg = test::config_from_text(good, {"output.directory=\"/tmp/x\""});
  CHECK(dir_cfg.where("output.directory") == "--set output.directory");
  dir_cfg.origins["output.directory"] = "--restart /tmp/x";
  CHECK(dir_cfg.where("output.directory") == "--restart /tmp/x");
}

TEST_CASE("the exact step is on by default in 2D and off in 3D and either way when set", "[config]") {
  CHECK(load_config(test::shipped("b1.cfg")).solver.active_set);
  CHECK_FALSE(load_config(test::shipped("corner-peel.cfg")).solver.active_set);
  CHECK(load_config(test::shipped("corner-peel.cfg"), {"solver.active_set=true"}).solver.active_set);
  CHECK_FALSE(load_config(test::shipped("b1.cfg"), {"solver.active_set=false"}).solver.active_set);
  // Block sweeps likewise: single in 2D (the exact step), twice per block in 3D.
  CHECK(load_config(test::shipped("b1.cfg")).solver.block_sweeps == 1);
  CHECK(load_config(test::shipped("corner-peel.cfg")).solver.block_sweeps == 2);
  CHECK(load_config(test::shipped("corner-peel.cfg"), {"solver.block_sweeps=1"}).solver.block_sweeps == 1);
  CHECK(load_config(test::shipped("b1.cfg"), {"solver.block_sweeps=3"}).solver.block_sweeps == 3);
}

TEST_CASE("a config saved with a UTF-8 byte-order mark is refused with what to change", "[config]") {
  const fs::path file = fs::temp_directory_path() / "rccm_test_bom.cfg";
  std::ofstream(file, std::ios::binary) << "\xEF\xBB\xBF" << good;
  CHECK_THROWS_WITH(load_config(file.string()),
                    file.string() + ":1: syntax error: the file starts with a UTF-8 byte-order mark, which libconfig "
                                    "does not read: save it as plain UTF-8");
  std::ofstream(file, std::ios::binary) << good;  // the same text without it
  CHECK_NOTHROW(load_config(file.string()));
  fs::remove(file);
}

TEST_CASE("a config through a pipe is read once and reads as the file", "[config]") {
  // `rccm run <(...)` or `cat cfg | rccm run /dev/stdin`: the path is a pipe's, /dev/fd/N, whose
  // bytes a second read of the path does not find (it read an empty config: "missing section").
  const auto through_pipe = [](const std::string& text, const std::vector<std::string>& overrides = {}) {
    int ends[2];
    REQUIRE(::pipe(ends) == 0);
    REQUIRE(::write(ends[1], text.data(), text.size()) == static_cast<ssize_t>(text.size()));  // within its buffer
    ::close(ends[1]);
    struct Closed {
      int fd;
      ~Closed() { ::close(fd); }
    } read_end{ends[0]};
    return load_config("/dev/fd/" + std::to_string(ends[0]), overrides);
  };
  const Config piped = through_pipe(good), file = test::config_from_text(good);
  CHECK(piped.settings == file.settings);
  CHECK(piped.lines == file.lines);
  CHECK_THROWS_WITH(through_pipe(good, {"interface.mu=-1"}), Catch::Contains("--set interface.mu: must be >= 0"));
  CHECK_THROWS_WITH(through_pipe(std::string(good) + "solver = { tolerance = 2.0; };\n"),
                    Catch::Matches("/dev/fd/[0-9]+:8: solver.tolerance: must be in \\(0, 1\\) \\(got 2\\)"));
  // A syntax error's hint reads the line from the bytes read, not from the drained pipe.
  CHECK_THROWS_WITH(through_pipe("\nmesh = { nx = nan; };\n"),
                    Catch::Matches("/dev/fd/[0-9]+:2: syntax error: 'nan' is no value: .*"));
}

TEST_CASE("a config beyond 16 MiB, a device and a NUL byte are refused", "[config]") {
  // /dev/zero was read without end (bad_alloc, exit 1); a NUL would end libconfig's read there.
  const fs::path big = fs::temp_directory_path() / "rccm_test_big.cfg";
  const std::size_t limit = 16 << 20;
  std::ofstream(big, std::ios::binary) << good << "#" << std::string(limit - std::strlen(good) - 2, 'x') << "\n";
  CHECK(fs::file_size(big) == limit);
  CHECK_NOTHROW(load_config(big.string()));
  std::ofstream(big, std::ios::app) << "\n";
  CHECK_THROWS_WITH(load_config(big.string()), big.string() + ": more than 16 MiB, not a config (a config is text of a "
                                                              "few kilobytes): the wrong file?");
  std::ofstream(big, std::ios::binary) << good << std::string(1, '\0') << "\n";
  CHECK_THROWS_WITH(load_config(big.string()), big.string() + ":8: a NUL byte: not a text file (a config is libconfig text)");
  fs::remove(big);
  CHECK_THROWS_WITH(load_config("/dev/zero"), "/dev/zero: neither a file nor a pipe (a device?): a config is a text file");
}

TEST_CASE("a length modulus or time below any physical magnitude is refused naming its setting", "[config]") {
  // Each was refused as another setting's fault: interface.boundary off the mesh's boundary,
  // an ill-conditioned stiffness at loads, output.times beyond time.T.
  const std::string b1 = test::shipped("b1.cfg");
  const std::string rule = " (the units are mm, N, MPa, s: a smaller value is no physical one)";
  CHECK_THROWS_WITH(load_config(b1, {"mesh.size=[1e-300,1e-300]"}), "--set mesh.size: must be at least 1e-9 mm" + rule + " (got 1e-300)");
  CHECK_THROWS_WITH(load_config(b1, {"material.E=1e-300"}), "--set material.E: must be at least 1e-9 MPa" + rule + " (got 1e-300)");
  CHECK_THROWS_WITH(load_config(b1, {"interface.Cn=1e-10"}), "--set interface.Cn: must be at least 1e-9 MPa/mm" + rule + " (got 1e-10)");
  CHECK_THROWS_WITH(load_config(b1, {"time.T=1e-300"}), "--set time.T: must be at least 1e-9 s" + rule + " (got 1e-300)");
  // Small but physical: a micrometre film, a 1 kPa gel, a microsecond; and the least itself.
  const Config small = load_config(b1, {"mesh.size=[1e-3,1e-9]", "material.E=1e-3", "interface.Cn=1e-9", "interface.Ct=1e-9",
                                         "time.T=1e-6", "output.times=[1e-6]"});
  CHECK(small.mesh.size[1] == 1e-9);
  CHECK(small.bodies.at(0).material.E == 1e-3);
  CHECK(small.time.T == 1e-6);
  // A stiffness ratio beyond double precision names the settings that make it.
  CHECK_THROWS_WITH(test::make_model(load_config(b1, {"material.E=1e-9"})),
                    Catch::Contains(": loads: the structure's stiffness is ill-conditioned") &&
                        Catch::Contains("(interface.Cn and Ct times each contact node's length or area a, which the "
                                        "mesh's size sets) against the body's material.E"));
}

TEST_CASE("a missing file is named", "[config]") {
  CHECK_THROWS_WITH(load_config("/nonexistent/b1.cfg"), Catch::Contains("/nonexistent/b1.cfg: cannot read"));
}

TEST_CASE("@include finds its file next to the config, wherever rccm runs from", "[config]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_include";
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "material.cfg") << "material = { E = 1000; nu = 0.3; };\n";
  std::ofstream(dir / "sub" / "main.cfg") << R"(mesh = { size = [10.0, 5.0]; nx = 4; ny = 2; };
@include "material.cfg"
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; };
)";
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);  // not the config's directory
  Config c;
  CHECK_NOTHROW(c = load_config("sub/main.cfg"));
  fs::current_path(cwd);
  CHECK(c.bodies.at(0).material.E == 1000.0);
  // An error in the included file names it as a path from where rccm runs, to open it there.
  std::ofstream(dir / "sub" / "material.cfg") << "material = { E = -1000; nu = 0.3; };\n";
  fs::current_path(dir);
  CHECK_THROWS_WITH(load_config("sub/main.cfg"), Catch::StartsWith("sub/material.cfg:1: material.E: must be > 0"));
  std::ofstream(dir / "sub" / "material.cfg") << "material = { E = ; nu = 0.3; };\n";
  CHECK_THROWS_WITH(load_config("sub/main.cfg"), Catch::StartsWith("sub/material.cfg:1: syntax error"));
  fs::current_path(cwd);
  fs::remove_all(dir);
}

TEST_CASE("a setting the run's methods do not read is noted with its line and who reads it and changes nothing", "[config]") {
  // Each setting, with overrides under which this run reads it and overrides under which it
  // does not; its value, where it can be, one that would change the run where it is read (not
  // a default, a cap that binds), so that running both ways checks the table.
  struct Case {
    std::string setting;
    std::vector<std::vector<std::string>> read, unread;
  };
  const std::vector<Case> cases{
      {"solver.over_relaxation=1.2", {{"solver.method=\"rccm\""}}, {{}, {"solver.method=\"newton\""}}},
      {"solver.local_iterations=10", {{}, {"solver.method=\"newton\""}}, {{"solver.method=\"rccm\""}, {"solver.form=\"jacobi\""}}},
      {"solver.form=\"jacobi\"", {{}}, {{"solver.method=\"newton\""}}},
      {"solver.anderson=0", {{}}, {{"solver.form=\"jacobi\""}, {"solver.form=\"jacobi\"", "solver.active_set=false"}, {"solver.method=\"newton\""}}},
      {"solver.block_sweeps=3", {{}}, {{"solver.form=\"jacobi\""}, {"solver.method=\"newton\""}, {"solver.method=\"rccm\""}}},
      {"solver.relaxation=0.5", {{"solver.form=\"jacobi\""}}, {{}, {"solver.method=\"rccm\""}}},
      {"solver.active_set=false", {{}}, {{"solver.method=\"newton\""}}},
      {"solver.active_set_max_nodes=2", {{}}, {{"solver.method=\"rccm\""}, {"solver.active_set=false"}}},
      {"solver.compressed_min_nodes=2", {{}, {"solver.method=\"newton\""}}, {{"solver.method=\"rccm\""}}},
      {"solver.linear_tolerance=1e-8", {{"solver.linear=\"cg-gamg\""}, {"solver.linear=\"mumps\""}},
       {{"solver.linear=\"cholmod\""}, {}, {"solver.linear=\"auto\""}}},  // auto: CHOLMOD in one process
      {"solver.out_of_core=true", {{"solver.linear=\"mumps\""}},
       {{"solver.linear=\"cholmod\""}, {}, {"solver.linear=\"cg-gamg\""}}},
      {"integrator.scheme=\"erk\"", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.table=\"ARKODE_SDIRK_5_3_4\"", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.rtol=1e-7", {{}}, {{"integrator.method=\"euler\""}, {"interface.alpha=0"}}},
      {"integrator.atol=1e-9", {{}}, {{"integrator.method=\"contact-only\""}}},
      {"integrator.max_step=0.1", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.initial_step=0.01", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.fixed_step=0.1", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.min_step=0.01", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.max_steps=3", {{}}, {{"integrator.method=\"euler\""}}},
      {"integrator.fixed_point_tolerance=1e-4", {{"integrator.method=\"rate-independent\""}}, {{}}},
      {"integrator.fixed_point_iterations=1", {{"interface.alpha=0"}}, {{}}}};
  for (const Case& c : cases) {
    const std::string name = c.setting.substr(0, c.setting.find('='));
    for (bool read : {true, false})
      for (std::vector<std::string> overrides : read ? c.read : c.unread) {
        overrides.push_back(c.setting);
        const std::vector<std::string> notes = unused_settings(test::config_from_text(good, overrides));
        INFO(c.setting << (read ? " read" : " unread") << " with " << (overrides.size() > 1 ? overrides.front() : "defaults"));
        CHECK(notes.size() == (read ? 0u : 1u));
        if (!read && !notes.empty()) CHECK_THAT(notes[0], Catch::StartsWith("--set " + name + ": not read by "));
        if (!read) {  // and indeed changes nothing: the run with it and without it, to the last bit
          const RunResult with = Simulation(test::config_from_text(good, overrides), {}).run();
          overrides.pop_back();
          const RunResult without = Simulation(test::config_from_text(good, overrides), {}).run();
          REQUIRE(with.snapshots.size() == without.snapshots.size());
          CHECK(with.steps.size() == without.steps.size());
          CHECK(with.solves.sweeps == without.solves.sweeps);
          for (std::size_t k = 0; k < with.snapshots.size(); ++k) {
            CHECK(with.snapshots[k].beta == without.snapshots[k].beta);
            CHECK(with.snapshots[k].Rbar == without.snapshots[k].Rbar);
            CHECK(with.snapshots[k].u == without.snapshots[k].u);
          }
        }
      }
  }
  // The rate-independent limit chosen by alpha = 0 says so.
  CHECK_THAT(unused_settings(test::config_from_text(good, {"integrator.rtol=1e-7", "interface.alpha=0"})).at(0),
             Catch::Contains("the \"rate-independent\" integrator (alpha = 0 on every interface), only by \"arkode\""));
  CHECK_THAT(unused_settings(test::config_from_text(good, {"integrator.rtol=1e-7", "integrator.method=\"rate-independent\""})).at(0),
             !Catch::Contains("alpha = 0"));
  // "auto" in one process is CHOLMOD, and said so as "cholmod" is (it went without a note).
  for (const char* linear : {"\"auto\"", "\"cholmod\""})
    CHECK(unused_settings(test::config_from_text(good, {std::string("solver.linear=") + linear, "solver.linear_tolerance=1e-8"})) ==
          std::vector<std::string>{"--set solver.linear_tolerance: not read by CHOLMOD (solver.linear = \"cholmod\", or "
                                   "\"auto\" in one process), only by solver.linear = \"cg-gamg\" and \"mumps\" (\"auto\" "
                                   "under mpirun); it has no effect on this run"});
  CHECK_THAT(unused_settings(test::config_from_text(good, {"solver.linear=\"cg-gamg\"", "solver.out_of_core=true"})).at(0),
             Catch::Contains("not read by PETSc CG + GAMG (solver.linear = \"cg-gamg\"), only by solver.linear = \"mumps\""));
  CHECK(test::config_from_text(good, {"solver.linear=\"mumps\"", "solver.out_of_core=true"}).solver.linear.out_of_core);
  CHECK(!test::config_from_text(good, {"solver.linear=\"mumps\""}).solver.linear.out_of_core);
  // The 3D Newton step reads a compressed W0 too; the classical rccm solver keeps W0 dense.
  for (const char* method : {"newton", "rccm"}) {
    const std::vector<std::string> peel =
        unused_settings(test::corner_peel(2, {std::string("solver.method=\"") + method + "\"", "solver.compressed_min_nodes=100"}));
    INFO(method);
    CHECK(std::count_if(peel.begin(), peel.end(), [](const std::string& n) { return n.find("compressed_min_nodes") != n.npos; }) ==
          (std::string(method) == "rccm" ? 1 : 0));
  }
  // A setting written in the file is named by its line (the run says it before its first
  // step, not as a doubt about its results: tests/check_command_line.sh).
  const Config c = test::config_from_text(std::string(good) + "solver = { method = \"newton\"; anderson = 3; };\n");
  const std::vector<std::string> notes = unused_settings(c);
  CHECK(test::make_model(c).notes().empty());
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == c.file + ":8: solver.anderson: not read by the \"newton\" solver, only by the \"bipotential\" solver's "
                             "Gauss-Seidel form; it has no effect on this run");
  // The shipped configs write none, whichever methods `rccm compare` gives them.
  for (const char* file : {"b1.cfg", "b2.cfg", "corner-peel.cfg"})
    for (const char* method : {"arkode", "euler", "rate-independent", "contact-only"})
      for (const char* solver : {"bipotential", "rccm", "newton"})
        CHECK(unused_settings(load_config(test::shipped(file), {std::string("integrator.method=\"") + method + "\"",
                                                                 std::string("solver.method=\"") + solver + "\""}))
                  .empty());
}

TEST_CASE("an output directory holding a folder named as a file rccm writes is refused before the run", "[config]") {
  // The run would compute to the end and fail where it writes interface_t1.csv (exit 3): it is
  // refused at once instead, with --force too; a folder of another name is the user's own.
  const std::filesystem::path dir = std::filesystem::path(RCCM_TEST_TMP) / "folder_named_alike";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "mine" / "sub");
  Config cfg = test::config_from_text(good);
  cfg.output.directory = dir.string();
  CHECK_NOTHROW(check_output_directory(cfg, false));
  std::filesystem::create_directories(dir / "interface_t1.csv" / "sub");
  for (bool force : {false, true})
    CHECK_THROWS_WITH(check_output_directory(cfg, force),
                      Catch::Contains("interface_t1.csv' is not a file but has the name of one rccm writes there"));
  std::filesystem::remove_all(dir);
}
