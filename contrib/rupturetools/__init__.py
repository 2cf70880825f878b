"""Python tools around rupture: readers of the program's files and the
studies built on them. The scripts in contrib/ are thin command-line entry
points over this package; its tests are in contrib/tests (pytest)."""
