// Output::Series, the rows of a time series: kept in memory, in a file (on
// the process that writes the series: a run of a million steps holds no
// rows in memory) or not at all (only the count and the last row). The
// same rows come back in the same order in each way, across the batches in
// which the file is appended to; a checkpoint's copy (save()) is byte for
// byte what BinaryIO writes for a list of rows, and load() brings it back;
// clear() empties the file; the file goes with the series; a file cut
// short during the run is named in the error.

#include <rupture/base/binary_io.h>
#include <rupture/output/series.h>

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

namespace
{
  std::vector<double>
  row_of(const unsigned int i)
  {
    // 7 numbers, as a fault station's row; not representable in decimal.
    std::vector<double> row(7);
    for (unsigned int c = 0; c < row.size(); ++c)
      row[c] = (i + 1) / 3. + c * 1e-17 + c;
    return row;
  }

  std::vector<std::vector<double>>
  rows_of(const rupture::Output::Series &series)
  {
    std::vector<std::vector<double>> rows;
    series.for_each([&](const std::vector<double> &r) { rows.push_back(r); });
    return rows;
  }
} // namespace

int
main()
{
  namespace fs = std::filesystem;
  using rupture::Output::Series;
  // 20000 rows of 7 numbers: the file is appended to in batches of 65536
  // numbers, so the rows cross two batch boundaries.
  const unsigned int               n = 20000;
  std::vector<std::vector<double>> expected;
  for (unsigned int i = 0; i < n; ++i)
    expected.push_back(row_of(i));

  Series in_memory, in_file, none;
  none.keep_rows(false);
  for (unsigned int i = 0; i < n / 2; ++i)
    {
      in_memory.append(expected[i]);
      in_file.append(expected[i]);
      none.append(expected[i]);
    }
  // The rows so far go to the file with it.
  in_file.keep_in_file("series.rows");
  for (unsigned int i = n / 2; i < n; ++i)
    {
      in_memory.append(expected[i]);
      in_file.append(expected[i]);
      none.append(expected[i]);
    }
  std::cout << "rows: memory " << in_memory.size() << ", file "
            << in_file.size() << ", none " << none.size() << "\n"
            << "the same rows in memory and in the file: "
            << (rows_of(in_memory) == expected && rows_of(in_file) == expected ?
                  "yes" :
                  "no")
            << "\n"
            << "the last row kept without rows: "
            << (none.last() == expected.back() ? "yes" : "no") << "\n"
            << "file size: " << fs::file_size("series.rows") << " bytes ("
            << n * 7 * sizeof(double) << " expected)\n";

  // A checkpoint's copy.
  std::ostringstream binary, saved;
  rupture::BinaryIO::write(binary, expected);
  in_file.save(saved);
  std::cout << "save() is BinaryIO's list of rows: "
            << (saved.str() == binary.str() ? "yes" : "no") << "\n";
  {
    Series loaded;
    loaded.keep_in_file("loaded.rows");
    loaded.append(row_of(99));
    std::istringstream in(saved.str());
    loaded.load(in);
    std::cout << "load() brings the rows back (replacing its own): "
              << (rows_of(loaded) == expected ? "yes" : "no") << "\n";
  }
  std::cout << "the file goes with its series: "
            << (fs::exists("loaded.rows") ? "no" : "yes") << "\n";

  in_file.clear();
  std::cout << "after clear(): " << in_file.size() << " rows, file of "
            << fs::file_size("series.rows") << " bytes\n";

  // A file cut short behind the series' back.
  for (unsigned int i = 0; i < 3; ++i)
    in_file.append(expected[i]);
  in_file.for_each([](const std::vector<double> &) {});
  fs::resize_file("series.rows", 7 * sizeof(double));
  try
    {
      in_file.for_each([](const std::vector<double> &) {});
      std::cout << "a short file: not noticed\n";
    }
  catch (const dealii::ExceptionBase &e)
    {
      // (deal.II breaks the message into lines.)
      const std::string what = e.what();
      std::cout << "a short file: named in the error: "
                << (what.find("The file <series.rows>") != std::string::npos &&
                        what.find("shorter") != std::string::npos ?
                      "yes" :
                      "no")
                << "\n";
    }
}
