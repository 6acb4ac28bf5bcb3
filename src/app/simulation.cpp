#include "rccm/app/simulation.hpp"

#include "rccm/app/stop_request.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/contact/contact_solver.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/model/model.hpp"
#include "rccm/time/beta_ode.hpp"
#include "rccm/time/integrator.hpp"

namespace rccm {

RunResult Simulation::run() {
  Recorder recorder(cfg_, options_);                  // the output directory checked, or the checkpoint read
  Model model(cfg_, mesh_ ? std::move(*mesh_) : make_mesh(cfg_));  // loads, body (K0 factorized), interface, W0
  mesh_.reset();
  writing_started();                                  // a signal from now on stops at an accepted step
  recorder.open(model);                               // result files, only now that the input is known good
  BetaOde ode(model, make_contact_solver(cfg_.solver), [&](const AcceptedStep& a) {
    share_stop_request();  // mpirun: all processes stop at one step; before the writes, process 0's alone
    recorder.step(a);                                 // energy, files, logs, checkpoints
    if (a.step > 0) throw_if_stop_requested(a.step, a.t);  // step 0 is recorded before the integrator exists
  });
  if (cfg_.integrator.method == Method::Arkode)  // the energy terms to the order of the scheme
    ode.track_midpoints(make_contact_solver(cfg_.solver));
  recorder.start(ode);  // beta0 at t = 0, or the checkpoint's state
  const auto integrator = make_integrator(ode, cfg_, recorder.initial_step());
  recorder.attach(*integrator);
  try {
    for (double t_out : stop_times(cfg_.time.T, cfg_.output.times)) {
      if (recorder.has_snapshot(t_out)) continue;  // taken before a restart's checkpoint
      if (ode.committed_time() < t_out - 1e-12 * cfg_.time.T)
        integrator->advance(t_out);  // beta to t_out: one contact solve per stage, one per accepted step
      recorder.snapshot();           // the interface and the mesh at t_out
    }
  } catch (const SolveError& e) {  // the files end at the last accepted step, the message says where
    throw SolveError(e.what() + recorder.stop(std::string("failed: ") + e.what()));
  } catch (const Interrupted& e) {
    recorder.stop(e.what());
    throw;
  }
  return recorder.finish();
}

}  // namespace rccm
