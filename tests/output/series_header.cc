// The time-step line of the station and receiver files: one line when the
// rows are evenly spaced in time; when the step changed with the mesh, a
// second line gives the smallest and largest spacing.

#include <rupture/output/series_header.h>

#include <iostream>

int
main()
{
  using rupture::Output::time_step_lines;
  std::cout << "evenly spaced:\n"
            << time_step_lines({0., 0.5, 1., 1.5}, 0.5) << "a single row:\n"
            << time_step_lines({0.}, 0.5)
            << "a step halved after a mesh change:\n"
            << time_step_lines({0., 0.5, 1., 1.25, 1.5}, 0.25);
}
