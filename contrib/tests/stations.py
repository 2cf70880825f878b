"""Station files made for the tests of the study scripts."""

COLUMNS = "t h-slip h-slip-rate h-shear-stress\n"


def write_station(directory, name, start, peak, slip, problem="TPV101-2D"):
    """A SCEC-format station DIRECTORY/NAME.dat that starts slipping at
    @p start at rate @p peak for as long as it takes to slip @p slip."""
    rows = []
    t = 0.0
    while t < 10:
        rate = peak if start <= t < start + slip / peak else 0.0
        done = min(max(t - start, 0.0) * peak, slip)
        rows.append("%g %g %g 70" % (t, done, rate))
        t += 0.01
    (directory / (name + ".dat")).write_text(
        "# problem=%s\n" % problem + COLUMNS + "\n".join(rows) + "\n")
