// Helpers for rupture's .cc tests: run the program as the command line
// would, quietly, and read back what it wrote.
#ifndef rupture_tests_h
#define rupture_tests_h

#include <rupture/simulator/run.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace tests
{
  /**
   * Run rupture with @p arguments. The screen output is swallowed unless
   * @p verbose; errors still reach std::cerr, which the test compares.
   */
  inline int
  run(const std::vector<std::string> &arguments, const bool verbose = false)
  {
    std::ostringstream sink;
    std::streambuf    *old = std::cout.rdbuf();
    if (!verbose)
      std::cout.rdbuf(sink.rdbuf());
    const int code = rupture::run_program(arguments, MPI_COMM_WORLD);
    std::cout.rdbuf(old);
    return code;
  }

  /**
   * Run rupture quietly on the processes of @p communicator only (e.g.
   * the first process alone, to write a checkpoint that the others then
   * continue with it).
   */
  inline int
  run_on(const MPI_Comm communicator, const std::vector<std::string> &arguments)
  {
    std::ostringstream sink;
    std::streambuf    *old  = std::cout.rdbuf(sink.rdbuf());
    const int          code = rupture::run_program(arguments, communicator);
    std::cout.rdbuf(old);
    return code;
  }

  /**
   * Run rupture quietly with @p arguments plus "--set S" for each S of
   * @p settings and <Output directory> = @p directory, which the first
   * process removes before the run; every process waits for that and for
   * the end of the run.
   */
  inline int
  run_in(const std::string              &directory,
         std::vector<std::string>        arguments,
         const std::vector<std::string> &settings,
         const MPI_Comm                  communicator = MPI_COMM_WORLD)
  {
    arguments.push_back("--set");
    arguments.push_back("Output directory=" + directory);
    for (const auto &s : settings)
      {
        arguments.push_back("--set");
        arguments.push_back(s);
      }
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::remove_all(directory);
    MPI_Barrier(communicator);
    const int code = run(arguments);
    MPI_Barrier(communicator);
    return code;
  }

  /**
   * A boundary-integral run of @p prm in @p directory as if it had been
   * killed after the checkpoint before its last one (the newest removed,
   * the previous put in its place), continued by --resume with the run's
   * @p settings; the screen output is shown if @p verbose.
   */
  inline int
  resume_from_previous_checkpoint(const std::string              &prm,
                                  const std::string              &directory,
                                  const std::vector<std::string> &settings,
                                  const bool verbose = false)
  {
    namespace fs            = std::filesystem;
    const std::string where = directory + "/checkpoint/boundary_integral";
    // (One process moves the files; the others wait for it.)
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      {
        fs::remove(where + ".bin");
        fs::rename(where + ".previous.bin", where + ".bin");
      }
    MPI_Barrier(MPI_COMM_WORLD);
    std::vector<std::string> resume = {prm, "--resume"};
    for (const auto &s : settings)
      resume.insert(resume.end(), {"--set", s});
    resume.insert(resume.end(), {"--set", "Output directory=" + directory});
    return run(resume, verbose);
  }

  /**
   * Run rupture with @p arguments, swallowing the screen output and
   * returning what it wrote to std::cerr in @p errors.
   */
  inline int
  run_capture(const std::vector<std::string> &arguments, std::string &errors)
  {
    std::ostringstream sink, error_sink;
    std::streambuf    *old     = std::cout.rdbuf(sink.rdbuf());
    std::streambuf    *old_err = std::cerr.rdbuf(error_sink.rdbuf());
    const int          code = rupture::run_program(arguments, MPI_COMM_WORLD);
    std::cout.rdbuf(old);
    std::cerr.rdbuf(old_err);
    errors = error_sink.str();
    return code;
  }

  /**
   * The rows of an <output>/statistics file, or of any table of numbers
   * with '#' comment lines and a line of field names (station and receiver
   * files).
   */
  inline std::vector<std::vector<double>>
  read_statistics(const std::string &file)
  {
    std::vector<std::vector<double>> rows;
    std::ifstream                    in(file);
    std::string                      line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::istringstream  s(line);
        std::vector<double> row;
        double              v;
        while (s >> v)
          row.push_back(v);
        if (!row.empty()) // skips lines of column names
          rows.push_back(row);
      }
    return rows;
  }

  /// The largest difference of two tables (of read_statistics()) relative
  /// to their largest entry; 1e300 where their shapes differ or they are
  /// empty.
  inline double
  relative_difference(const std::vector<std::vector<double>> &a,
                      const std::vector<std::vector<double>> &b)
  {
    if (a.size() != b.size() || a.empty())
      return 1e300;
    double largest = 0, diff = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        if (a[i].size() != b[i].size())
          return 1e300;
        for (unsigned int j = 0; j < a[i].size(); ++j)
          {
            largest = std::max(largest, std::abs(a[i][j]));
            diff    = std::max(diff, std::abs(a[i][j] - b[i][j]));
          }
      }
    return diff / std::max(largest, 1e-300);
  }

  /**
   * The columns that <Mesh refinement> adds to a statistics file, one
   * entry per step: the DoFs and the energy the mesh changes have added so
   * far, found by their names in the file's header ("# N: name"), since
   * their place depends on the run (a fault, absorbing boundaries).
   */
  struct AdaptiveColumns
  {
    std::vector<double> dofs, remeshing;
  };

  inline AdaptiveColumns
  read_adaptive_columns(const std::string &file)
  {
    // The header's column numbers (from 1) of the two names.
    unsigned int  dofs = 0, remeshing = 0;
    std::ifstream in(file);
    std::string   line;
    while (std::getline(in, line) && !line.empty() && line[0] == '#')
      {
        std::istringstream s(line.substr(1));
        unsigned int       n = 0;
        char               colon;
        std::string        name;
        if (s >> n >> colon && std::getline(s >> std::ws, name))
          {
            if (name == "Degrees of freedom")
              dofs = n;
            else if (name.rfind("Energy added by mesh changes", 0) == 0)
              remeshing = n;
          }
      }
    AdaptiveColumns columns;
    if (dofs == 0 || remeshing == 0)
      return columns;
    for (const auto &row : read_statistics(file))
      if (row.size() >= std::max(dofs, remeshing))
        {
          columns.dofs.push_back(row[dofs - 1]);
          columns.remeshing.push_back(row[remeshing - 1]);
        }
    return columns;
  }

  /**
   * The rows of numbers of a CSV file such as events.csv: lines that start
   * with '#' and the line of column names (the first other line) left out.
   */
  inline std::vector<std::vector<double>>
  read_csv(const std::string &file)
  {
    std::vector<std::vector<double>> rows;
    std::ifstream                    in(file);
    std::string                      line;
    bool                             names = true;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        if (names)
          {
            names = false;
            continue;
          }
        std::vector<double> row;
        std::istringstream  fields(line);
        std::string         field;
        while (std::getline(fields, field, ','))
          row.push_back(std::stod(field));
        rows.push_back(row);
      }
    return rows;
  }

  /**
   * The rupture time of a fault station's table (as read_statistics()
   * gives it): the first time (column 0) at which the along-strike slip
   * rate (column 2) exceeds 1 mm/s; -1 if it never does.
   */
  inline double
  rupture_time(const std::vector<std::vector<double>> &rows)
  {
    for (const auto &row : rows)
      if (row.size() > 2 && std::abs(row[2]) > 1e-3)
        return row[0];
    return -1;
  }

  /**
   * The number after @p key on the first line of @p file that contains it.
   */
  inline double
  find_number(const std::string &file, const std::string &key)
  {
    std::ifstream in(file);
    std::string   line;
    while (std::getline(in, line))
      {
        const auto pos = line.find(key);
        if (pos != std::string::npos)
          return std::stod(line.substr(pos + key.size()));
      }
    return -1;
  }

  inline bool
  file_exists(const std::string &file)
  {
    return std::ifstream(file).good();
  }

  inline std::string
  read_file(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /**
   * The values of the DataArray named @p name of the ASCII VTK file text
   * @p vtu (in file order; empty if there is none).
   */
  inline std::vector<double>
  vtu_field(const std::string &vtu, const std::string &name)
  {
    const std::string   tag = "Name=\"" + name + "\"";
    std::vector<double> values;
    const auto          at = vtu.find(tag);
    if (at == std::string::npos)
      return values;
    const auto         start = vtu.find('>', at) + 1;
    std::istringstream in(
      vtu.substr(start, vtu.find("</DataArray>", at) - start));
    double v;
    while (in >> v)
      values.push_back(v);
    return values;
  }
} // namespace tests

#endif
