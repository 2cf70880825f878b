// Checkpoints and restart: the state after a step, written so that a run
// stopped at any moment continues from its last checkpoint (doc/manual.md,
// "Checkpoints and restart").
//
// A checkpoint is a directory <output>/checkpoint/step-NNNNNNNNN:
// - mesh, mesh_fixed.data, mesh.info: the p4est forest with the fields
//   attached (deal.II's Triangulation::save() and SolutionTransfer), which
//   load on any number of ranks;
// - fault.N: the fault node pairs that rank N owned, keyed by location;
// - state: rank 0's scalars, the parameters of the run, the statistics,
//   the output series (snapshot lists, station and receiver rows) and the
//   termination criteria's memory.
// It is written into checkpoint/writing and renamed when complete, so a
// run killed while writing leaves the earlier checkpoints intact; the two
// newest are kept.

#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/distributed/solution_transfer.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace rupture
{
  namespace
  {
    namespace fs = std::filesystem;

    /// Version 2 names every scalar of the state (version 1, a list of 24
    /// numbers by position, is still read).
    const char *const format_name    = "rupture checkpoint 2";
    const char *const format_name_v1 = "rupture checkpoint 1";

    /// The names of version 1's 24 scalars, in their order (the first four
    /// describe the checkpoint).
    const std::vector<std::string> v1_names = {"checkpoint/dimension",
                                               "checkpoint/ranks",
                                               "checkpoint/DoFs",
                                               "checkpoint/fields",
                                               "time/time",
                                               "time/phase time",
                                               "time/step",
                                               "time/dynamic start",
                                               "time/in dynamic phase",
                                               "time/time step",
                                               "energy/initial",
                                               "energy/kinetic",
                                               "energy/strain",
                                               "energy/external work",
                                               "energy/damping dissipation",
                                               "energy/absorbed",
                                               "energy/fault work",
                                               "output/next output time",
                                               "output/next fault output time",
                                               "output/peak slip rate",
                                               "newton/last linear iterations",
                                               "newton/last iterations",
                                               "time/phase start time",
                                               "time/steps in phase"};

    /// The entries of a parameter file printed as ShortPRM, by path.
    std::map<std::string, std::string>
    entries_of(const std::string &text)
    {
      std::map<std::string, std::string> entries;
      std::vector<std::string>           path;
      std::istringstream                 in(text);
      std::string                        line;
      while (std::getline(in, line))
        {
          line = dealii::Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(dealii::Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              const auto  eq   = line.find('=');
              std::string name = dealii::Utilities::trim(line.substr(
                4, eq == std::string::npos ? std::string::npos : eq - 4));
              std::string key;
              for (const auto &p : path)
                key += p + "/";
              entries[key + name] =
                eq == std::string::npos ?
                  "" :
                  dealii::Utilities::trim(line.substr(eq + 1));
            }
        }
      return entries;
    }

    /// Entries a continued run may change: where and how long it runs, and
    /// when it ends or writes checkpoints.
    bool
    may_change(const std::string &entry)
    {
      return entry == "Time integration/End time" ||
             entry.rfind("Termination/", 0) == 0 ||
             entry.rfind("Checkpoint/", 0) == 0 ||
             entry == "Output/Screen output interval" || entry == "Test mode";
    }
  } // namespace



  template <int dim>
  std::string
  Simulator<dim>::newest_checkpoint() const
  {
    const fs::path  base = fs::path(output_directory->name()) / "checkpoint";
    std::error_code error;
    std::string     newest;
    if (!fs::is_directory(base, error))
      return newest;
    for (const auto &entry : fs::directory_iterator(base, error))
      {
        const std::string name = entry.path().filename().string();
        if (name.rfind("step-", 0) == 0 &&
            fs::is_regular_file(entry.path() / "state", error) &&
            entry.path().string() > newest)
          newest = entry.path().string();
      }
    return newest;
  }



  template <int dim>
  void
  Simulator<dim>::check_checkpoint_parameters(ParameterHandler &prm) const
  {
    std::ifstream in(checkpoints.resume_from + "/state", std::ios::binary);
    std::string   format, parameters;
    BinaryIO::read(in, format);
    AssertThrow(format == format_name || format == format_name_v1,
                ExcMessage("<" + checkpoints.resume_from +
                           "/state> is not a checkpoint of this version of "
                           "rupture."));
    BinaryIO::read(in, parameters);
    std::ostringstream now;
    prm.print_parameters(now, ParameterHandler::ShortPRM);
    const auto before = entries_of(parameters), after = entries_of(now.str());
    for (const auto &[entry, value] : after)
      {
        const auto        at = before.find(entry);
        const std::string old_value =
          at == before.end() ? std::string("(not set)") : at->second;
        AssertThrow(value == old_value || may_change(entry),
                    ExcMessage("The checkpoint <" + checkpoints.resume_from +
                               "> was written with <" + entry + "> = '" +
                               old_value + "', but this run has '" + value +
                               "'. A run continues only with the parameters "
                               "it started with; only <Time integration/End "
                               "time>, the <Termination> and <Checkpoint> "
                               "entries and <Output/Screen output interval> "
                               "may change. Run without --resume to start "
                               "anew."));
      }

    // --refine: the phase the checkpoint continues must keep its time step
    // on the finer mesh (checked before the output directory is touched).
    if (checkpoints.refinements > 0)
      {
        BinaryIO::Records records;
        if (format == format_name_v1)
          {
            std::vector<double> s;
            BinaryIO::read(in, s);
            for (unsigned int k = 0; k < std::min(s.size(), v1_names.size());
                 ++k)
              records[v1_names[k]] = s[k];
          }
        else
          BinaryIO::read(in, records);
        const bool dynamic =
          !time_parameters.loading_phase ||
          BinaryIO::record(records, "time/in dynamic phase") != 0;
        AssertThrow(
          !(dynamic && time_parameters.scheme ==
                         TimeIntegration::Scheme::explicit_central_difference),
          ExcMessage(
            "--refine continues checkpoints of quasi-static and implicit "
            "phases (a loading phase, whatever its dynamic phase), but the "
            "checkpoint <" +
            checkpoints.resume_from +
            "> is in a phase of the explicit scheme, whose time step belongs "
            "to its mesh. Continue it without --refine, or refine from a "
            "checkpoint of its loading phase."));
      }
  }



  template <int dim>
  std::vector<typename Simulator<dim>::VectorType *>
  Simulator<dim>::checkpoint_fields()
  {
    // The motion, and the forces of the last step that the energy sums'
    // trapezoidal rules use at the next one.
    std::vector<VectorType *> fields = {&state.displacement,
                                        &state.velocity,
                                        &state.acceleration,
                                        &energy.applied_force,
                                        &energy.damping_force,
                                        &energy.contact_force};
    if (elastic_system.has_absorbing())
      fields.push_back(&energy.absorbing_force);
    return fields;
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "Checkpoint");
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    const fs::path  base    = fs::path(output_directory->name()) / "checkpoint";
    const fs::path  writing = base / "writing";
    std::error_code error;
    if (rank == 0)
      {
        fs::remove_all(writing, error);
        fs::create_directories(writing, error);
      }
    std::string message = error ?
                            "The checkpoint directory <" + writing.string() +
                              "> cannot be created: " + error.message() :
                            std::string();
    Utilities::throw_if_any(message, communicator);

    // Named in the manifests first (under the name they will have), so
    // that a new run in this directory removes them like every other
    // result of this one.
    char step_name[32];
    std::snprintf(step_name, sizeof(step_name), "step-%09u", state.step);
    {
      const std::string final_dir    = std::string("checkpoint/") + step_name;
      std::vector<std::string> names = {"fault." + std::to_string(rank)};
      if (rank == 0)
        for (const char *name : {"mesh",
                                 "mesh.info",
                                 "mesh_fixed.data",
                                 "mesh_variable.data",
                                 "state"})
          names.emplace_back(name);
      for (const auto &name : names)
        {
          output_directory->record(final_dir + "/" + name);
          output_directory->record("checkpoint/writing/" + name);
        }
    }

    // The mesh with the fields.
    const std::vector<VectorType *> fields = checkpoint_fields();
    std::vector<VectorType>         ghosted(fields.size());
    std::vector<const VectorType *> pointers;
    for (unsigned int k = 0; k < fields.size(); ++k)
      {
        ghosted[k].reinit(discretization.locally_owned_dofs(),
                          discretization.locally_relevant_dofs(),
                          communicator);
        ghosted[k] = *fields[k];
        pointers.push_back(&ghosted[k]);
      }
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      discretization.dof_handler());
    transfer.prepare_for_serialization(pointers);
    discretization.triangulation().save((writing / "mesh").string());

    // This rank's fault pairs.
    if (fault)
      {
        std::ofstream out(writing / ("fault." + std::to_string(rank)),
                          std::ios::binary);
        fault->save(out);
        out.close();
        if (!out)
          message = "The checkpoint's fault file cannot be written.";
      }
    Utilities::throw_if_any(message, communicator);

    if (rank == 0)
      {
        std::ostringstream out;
        BinaryIO::write(out, std::string(format_name));
        BinaryIO::write(out, checkpoints.parameters_text);
        BinaryIO::Records records;
        records["checkpoint/dimension"] = dim;
        records["checkpoint/ranks"]     = n_ranks;
        records["checkpoint/DoFs"]      = discretization.dof_handler().n_dofs();
        records["checkpoint/fields"]    = fields.size();
        state.save(records);
        energy.save(records);
        newton.status().save(records);
        output_schedule.save(records);
        records["output/peak slip rate"] = outcome.peak_slip_rate;
        integrator->save(records);
        BinaryIO::write(out, records);
        statistics.save(out);
        volume_output->save(out);
        receivers->save(out);
        if (fault)
          fault_output->save(out);
        termination.save(out);
        // Written last: a checkpoint is complete when its state is there.
        Utilities::write_file_atomically((writing / "state").string(),
                                         out.str());

        const fs::path done = base / step_name;
        fs::remove_all(done, error);
        fs::rename(writing, done, error);
        if (error)
          message = "The checkpoint <" + done.string() +
                    "> cannot be completed: " + error.message();
        // Keep the two newest complete ones.
        std::vector<std::string> all;
        for (const auto &entry : fs::directory_iterator(base, error))
          if (entry.path().filename().string().rfind("step-", 0) == 0 &&
              fs::is_regular_file(entry.path() / "state", error))
            all.push_back(entry.path().string());
        std::sort(all.begin(), all.end());
        for (unsigned int k = 0; k + 2 < all.size(); ++k)
          fs::remove_all(all[k], error);
      }
    Utilities::throw_if_any(message, communicator);
    checkpoints.last_write = MPI_Wtime();
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint()
  {
    TimerOutput::Scope t(timer, "Checkpoint");
    std::ifstream      in(checkpoints.resume_from + "/state", std::ios::binary);
    AssertThrow(in,
                ExcMessage("The checkpoint <" + checkpoints.resume_from +
                           "/state> cannot be read."));
    std::string format, parameters;
    BinaryIO::read(in, format);
    BinaryIO::read(in, parameters);
    BinaryIO::Records &records = checkpoints.records;
    if (format == format_name_v1)
      {
        // Version 1: the scalars by position.
        std::vector<double> s;
        BinaryIO::read(in, s);
        AssertThrow(s.size() == v1_names.size(),
                    ExcMessage("The checkpoint <" + checkpoints.resume_from +
                               "> is damaged."));
        records.clear();
        for (unsigned int k = 0; k < s.size(); ++k)
          records[v1_names[k]] = s[k];
      }
    else
      BinaryIO::read(in, records);
    const auto record = [&](const std::string &name) {
      return BinaryIO::record(records, name);
    };
    AssertThrow(record("checkpoint/dimension") == dim,
                ExcMessage("The checkpoint <" + checkpoints.resume_from +
                           "> is damaged or of another dimension."));
    AssertThrow(
      record("checkpoint/DoFs") == discretization.dof_handler().n_dofs(),
      ExcMessage("The checkpoint <" + checkpoints.resume_from + "> has " +
                 std::to_string(static_cast<long>(record("checkpoint/DoFs"))) +
                 " DoFs, this run " +
                 std::to_string(discretization.dof_handler().n_dofs()) +
                 ": it was written for another mesh."));
    const unsigned int n_saved_ranks =
      static_cast<unsigned int>(record("checkpoint/ranks"));

    // The fields, on this run's DoFs.
    std::vector<VectorType *> fields = checkpoint_fields();
    AssertThrow(fields.size() == record("checkpoint/fields"),
                ExcMessage("The checkpoint <" + checkpoints.resume_from +
                           "> holds other fields than this run needs."));
    for (VectorType *v : fields)
      v->reinit(discretization.locally_owned_dofs(), communicator);
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      discretization.dof_handler());
    transfer.deserialize(fields);
    for (VectorType *v : fields)
      discretization.distribute_hanging(*v);

    state.load(records);
    energy.load(records);
    newton.status().load(records);
    output_schedule.load(records);
    outcome.peak_slip_rate = record("output/peak slip rate");

    statistics.load(in);
    volume_output->load(in);
    receivers->load(in);
    if (fault)
      {
        fault_output->load(in);
        std::vector<std::string> files;
        for (unsigned int r = 0; r < n_saved_ranks; ++r)
          files.push_back(checkpoints.resume_from + "/fault." +
                          std::to_string(r));
        fault->load(files);
        fault->set_time(state.time);
      }
    termination.load(in);
    if (format == format_name_v1)
      {
        // Version 1 kept the implicit scheme's sub-stepping last.
        std::vector<double> integrator_state;
        BinaryIO::read(in, integrator_state);
        AssertThrow(integrator_state.empty() || integrator_state.size() == 2,
                    ExcMessage("The checkpoint's state of the implicit scheme "
                               "is damaged."));
        if (integrator_state.size() == 2)
          {
            records["integrator/substep depth"]     = integrator_state[0];
            records["integrator/steps without cut"] = integrator_state[1];
          }
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
