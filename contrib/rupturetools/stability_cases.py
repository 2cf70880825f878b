"""The stability study (contrib/stability-study): its base parameter files,
the case matrix and the 1-D analytic slip of the column."""

import math
import re


# ---------------------------------------------------------------------------
# The two base parameter files.

COLUMN_PRM = """\
# 1-D plane-wave slip-weakening interface (as tests/fault/inputs/plane_wave.prm):
# a column one cell wide, u_y held by rollers, so only the shear wave u_x(y, t)
# exists; fault at y = 0, absorbing ends at y = -4 and 4.
set Dimension = 2
set Test mode = false
set Output directory = output
subsection Scene
  set Model = box
  subsection Box
    set Lower corner = 0, -4
    set Upper corner = 0.05, 4
    set Number of cells = 1, 160
  end
end
subsection Material
  set Density = 1
  set P-wave speed = 2
  set S-wave speed = 1
end
subsection Fault
  set Model = penalty contact
  set Plane point = 0, 0
  set Plane normal = 0, 1
  set Normal penalty = 1e5
  set Tangential penalty = 1e5
  set Initial traction = 6.1; -10
  subsection Linear slip weakening
    set Static friction coefficient = 0.6
    set Dynamic friction coefficient = 0.5
    set Slip-weakening distance = 1
  end
end
subsection Boundary conditions
  set Roller = west: y, east: y
  set Absorbing = bottom, top
end
subsection Time integration
  set Scheme = implicit Newmark
  set Time step = 0.01
  set End time = 3
end
subsection Solver
  set Linear solver = direct
end
subsection Output
  set Output interval = -1
  set Screen output interval = 1
end
"""

INPLANE_PRM = """\
# Coarse 2-D in-plane rupture after TPV205-2D: TPV3 material and friction,
# sigma_n = 120 MPa, tau_0 = 70 MPa with an 81.6 MPa nucleation patch
# |x| <= 1.5 km, fault |x| <= 9 km (welded beyond), 625 m cells, absorbing
# boundaries all round.
set Dimension = 2
set Test mode = false
set Output directory = output
subsection Scene
  set Model = box
  subsection Box
    set Lower corner = -15000, -7500
    set Upper corner = 15000, 7500
    set Number of cells = 50, 24
  end
end
subsection Material
  set Density = 2670
  set P-wave speed = 6000
  set S-wave speed = 3464
end
subsection Fault
  set Model = penalty contact
  set Plane point = 0, 0
  set Plane normal = 0, 1
  set Fault region = (abs(x) <= 9000) ? 1 : 0
  set Normal penalty = 5e11
  set Tangential penalty = 5e11
  set Initial traction = (abs(x) <= 1500) ? 81.6e6 : 70e6; -120e6
  subsection Linear slip weakening
    set Static friction coefficient = 0.677
    set Dynamic friction coefficient = 0.525
    set Slip-weakening distance = 0.4
  end
end
subsection Boundary conditions
  set Absorbing = west, east, bottom, top
end
subsection Time integration
  set Scheme = implicit Newmark
  set Time step = 0.02
  set End time = 3
end
subsection Solver
  set Linear solver = direct
end
subsection Output
  set Output interval = -1
  set Screen output interval = 1
end
"""

RS_COLUMN_PRM = COLUMN_PRM.replace("set Initial traction = 6.1; -10",
                                   "set Initial traction = 6.5; -10") + """\
# The 1-D rate-and-state column (as tests/fault/rate_and_state_column.cc):
# regularised aging law, started stronger than its steady state; the slip
# rate rises to the steady state V = 1.
subsection Fault
  set Friction law = rate and state
  subsection Rate and state
    set Formulation = regularized
    set Evolution law = aging
    set Direct effect = 0.008
    set Evolution effect = 0.012
    set Characteristic slip distance = 0.1
    set Reference friction coefficient = 0.6
    set Reference slip rate = 1
    set Initial state = 1
  end
end
"""

PATCH3D_PRM = """\
# A 3-D miniature of TPV3 (as tests/fault/split_node_3d.prm and
# penalty_rupture_3d.prm): a vertical fault |x| <= 2 km, |z| <= 1.5 km in
# the plane y = 0, TPV3 material and friction, 500 m cells, absorbing
# boundaries all round; the prestress points 30 degrees from strike (x)
# towards -z, 70 MPa (81.6 MPa in the patch |x|, |z| <= 750 m) at 120 MPa
# compression.
set Dimension = 3
set Test mode = false
set Output directory = output
subsection Scene
  set Model = box
  subsection Box
    set Lower corner = -3000, -1500, -3000
    set Upper corner = 3000, 1500, 3000
    set Number of cells = 12, 6, 12
  end
end
subsection Material
  set Density = 2670
  set P-wave speed = 6000
  set S-wave speed = 3464
end
subsection Fault
  set Model = penalty contact
  set Plane point = 0, 0, 0
  set Plane normal = 0, 1, 0
  set Fault region = (abs(x) <= 2000 && abs(z) <= 1500) ? 1 : 0
  set Normal penalty = 6.4e9
  set Tangential penalty = 6.4e9
  set Initial traction = ((abs(x) <= 750 && abs(z) <= 750) ? 81.6e6 : 70e6) * 0.8660254; -120e6; -((abs(x) <= 750 && abs(z) <= 750) ? 81.6e6 : 70e6) * 0.5
  subsection Linear slip weakening
    set Static friction coefficient = 0.677
    set Dynamic friction coefficient = 0.525
    set Slip-weakening distance = 0.05
  end
end
subsection Boundary conditions
  set Absorbing = west, east, south, north, bottom, top
end
subsection Time integration
  set Scheme = implicit Newmark
  set Time step = 0.02
  set End time = 1.2
end
subsection Solver
  set Linear solver = direct
end
subsection Output
  set Output interval = -1
  set Screen output interval = 1
end
"""

# Properties of the bases that the case matrix and the analytic solution use.
BASES = {
    "column": dict(prm=COLUMN_PRM, rho=1.0, cs=1.0, cp=2.0, h=0.05,
                   end=3.0, dt=0.01, mu_s=0.6, mu_d=0.5, dc=1.0,
                   tau0=6.1, sigma=10.0, penalty=1e5),
    "rscolumn": dict(prm=RS_COLUMN_PRM, rho=1.0, cs=1.0, cp=2.0, h=0.05,
                     end=3.0, dt=0.01, mu_s=0.6, mu_d=0.5, dc=1.0,
                     tau0=6.5, sigma=10.0, penalty=1e5),
    "inplane": dict(prm=INPLANE_PRM, rho=2670.0, cs=3464.0, cp=6000.0,
                    h=15000.0 / 24, end=3.0, dt=0.02, mu_s=0.677,
                    mu_d=0.525, dc=0.4, tau0=70e6, sigma=120e6, penalty=5e11),
    "patch3d": dict(prm=PATCH3D_PRM, rho=2670.0, cs=3464.0, cp=6000.0,
                    h=500.0, end=1.2, dt=0.02, mu_s=0.677, mu_d=0.525,
                    dc=0.05, tau0=70e6, sigma=120e6, penalty=6.4e9),
}
for _b in BASES.values():
    # Elastic stiffness of a fault-adjacent element: shear modulus / cell size.
    _b["k_element"] = _b["rho"] * _b["cs"] ** 2 / _b["h"]

SCHEMES = {
    # label: (Fault/Model, Time integration/Scheme, Solver/Linear solver)
    "implicit": ("penalty contact", "implicit Newmark", "direct"),
    "implicit-gmres": ("penalty contact", "implicit Newmark", "automatic"),
    "explicit": ("traction at split nodes", "explicit central difference",
                 None),
}
SCHEME_LABEL = {
    "implicit": "implicit Newmark, penalty, direct solver",
    "implicit-gmres": "implicit Newmark, penalty, GMRES + AMG",
    "explicit": "explicit, split node",
}


def fmt(x, digits=3):
    """A short number: 0.01 -> 0.01, 12345 -> 1.23e+04."""
    if x is None:
        return "-"
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        return "%.*g" % (digits, x)
    return "%.*e" % (digits - 1, x)


# ---------------------------------------------------------------------------
# The case matrix.

class Case:
    def __init__(self, family, base, scheme, value, sets=(), name="",
                 dt_factor=None, analytic=None, quick=None, end=None):
        self.family = family
        self.base = base
        self.scheme = scheme
        self.value = value            # what the table shows in "value"
        self.name = name              # extra words for the "case" column
        self.sets = list(sets)
        self.dt_factor = dt_factor    # time step as a multiple of the stable explicit one
        self.analytic = analytic      # dict of overrides for the 1-D solution, or None
        self.quick = quick            # expected result in --quick ("ok"/"failed"), or None
        self.end = end                # End time, if not the base's
        words = [re.sub(r"[^a-z]+", "-", family.lower().replace("'s", "")), base, scheme,
                 re.sub(r"[^A-Za-z0-9.+-]+", "_", str(value))]
        if name:
            words.append(re.sub(r"[^A-Za-z0-9.+-]+", "_", name).strip("_"))
        self.id = "/".join(words)


def friction_sets(base, mu_d=None, dc=None):
    """Overrides of the friction law; a base value is left out, so that the
    case runs only once (see run_all)."""
    s = []
    prefix = "Fault/Linear slip weakening/"
    if mu_d is not None and mu_d != BASES[base]["mu_d"]:
        s.append(prefix + "Dynamic friction coefficient=%r" % mu_d)
    if dc is not None and dc != BASES[base]["dc"]:
        s.append(prefix + "Slip-weakening distance=%r" % dc)
    return s


def p_wave_sets(base, vp):
    if abs(vp - BASES[base]["cp"]) < 1e-4 * vp:
        return []
    return ["Material/P-wave speed=%.10g" % vp]


def p_wave_speed(cs, nu):
    return cs * math.sqrt((2 - 2 * nu) / (1 - 2 * nu))


def build_cases():
    cases = []
    both = ("implicit", "explicit")

    # 1. Penalty stiffness, a multiple of the fault-adjacent element's.
    for base, factors in (("column", [1e-2, 1e-1, 1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6]),
                          ("inplane", [1e-2, 1, 1e2, 1e4, 1e6])):
        for scheme in ("implicit", "implicit-gmres"):
            for f in factors:
                p = f * BASES[base]["k_element"]
                quick = None
                if base == "column" and scheme == "implicit" and f in (1e-2, 1e6):
                    quick = "ok"
                cases.append(Case("penalty", base, scheme, "%g x k_e" % f,
                                  ["Fault/Normal penalty=%.6g" % p,
                                   "Fault/Tangential penalty=%.6g" % p],
                                  name="p = %s" % fmt(p), quick=quick,
                                  analytic={} if base == "column" else None))

    # A penalty of zero cannot work.
    cases.append(Case("penalty", "column", "implicit", "0 x k_e",
                      ["Fault/Normal penalty=0", "Fault/Tangential penalty=0"],
                      name="p = 0"))

    # 2. Slip-weakening distance L_d (m).
    for base, values in (("column", [10, 1, 0.1, 1e-2, 1e-3, 1e-4]),
                         ("inplane", [10, 0.4, 1e-2, 1e-4])):
        for scheme in both:
            for dc in values:
                quick = "ok" if (base, scheme, dc) == ("column", "implicit", 1e-4) else None
                cases.append(Case("slip-weakening distance", base, scheme,
                                  "L_d = %g m" % dc, friction_sets(base, dc=dc),
                                  quick=quick,
                                  analytic={"dc": dc} if base == "column" else None))
    # The same with softer penalties: in the column 1 k_e, far below the
    # slip-weakening slope; in the in-plane base 100 k_e.
    for base, f, values in (("column", 1, [1e-4]), ("inplane", 100, [1e-2, 1e-4])):
        p = f * BASES[base]["k_element"]
        for dc in values:
            cases.append(Case("slip-weakening distance", base, "implicit",
                              "L_d = %g m" % dc,
                              friction_sets(base, dc=dc) +
                              ["Fault/Normal penalty=%.6g" % p, "Fault/Tangential penalty=%.6g" % p],
                              name="p = %g k_e = %s" % (f, fmt(p)),
                              analytic={"dc": dc} if base == "column" else None))

    cases.append(Case("slip-weakening distance", "column", "implicit", "L_d = 0 m",
                      friction_sets("column", dc=0.0)))

    # 3. Strength drop mu_0 - mu_d.
    for base, values in (("column", [1e-4, 1e-3, 1e-2, 0.1, 0.3, 0.5]),
                         ("inplane", [1e-4, 1e-2, 0.152, 0.5])):
        for scheme in both:
            for d in values:
                mu_d = round(BASES[base]["mu_s"] - d, 10)
                cases.append(Case("strength drop", base, scheme,
                                  "mu_0 - mu_d = %g" % d,
                                  friction_sets(base, mu_d=mu_d),
                                  name="mu_d = %g" % mu_d,
                                  analytic={"mu_d": mu_d} if base == "column" else None))

    # Strengthening instead of weakening cannot work.
    cases.append(Case("strength drop", "column", "implicit", "mu_0 - mu_d = -0.1",
                      friction_sets("column", mu_d=0.7), name="mu_d = 0.7"))

    # 4. Time step against the stable explicit step dt_c.
    explicit_factors = {"column": [0.01, 0.1, 0.5, 0.9, 1.0, 1.05, 1.2, 1.5, 2, 3, 5, 10, 100],
                        "inplane": [0.5, 1.0, 1.5, 2, 5, 10]}
    implicit_factors = {"column": [0.1, 1, 10, 100, 1000],
                        "inplane": [1, 10, 100]}
    for base in ("column", "inplane"):
        for f in explicit_factors[base]:
            quick = "failed" if (base, f) == ("column", 10) else None
            cases.append(Case("time step", base, "explicit", "%g x dt_c" % f,
                              ["Time integration/Allow unstable time step=true"],
                              dt_factor=f, quick=quick,
                              analytic={} if base == "column" else None))
        if base == "column":
            cases.append(Case("time step", base, "explicit", "1.05 x dt_c",
                              name="unstable step not allowed",
                              dt_factor=1.05, quick="failed",
                              analytic={}))
        for f in implicit_factors[base]:
            cases.append(Case("time step", base, "implicit", "%g x dt_c" % f,
                              dt_factor=f,
                              analytic={} if base == "column" else None))

    # 5. Poisson's ratio, by the P-wave speed at a fixed S-wave speed.
    for base, values in (("column", [0.45, 0.499]),
                         ("inplane", [0.25, 0.4, 0.45, 0.49, 0.499])):
        for scheme in both:
            for nu in values:
                vp = p_wave_speed(BASES[base]["cs"], nu)
                quick = "ok" if (base, scheme, nu) == ("column", "explicit", 0.499) else None
                cases.append(Case("Poisson's ratio", base, scheme, "nu = %g" % nu,
                                  p_wave_sets(base, vp),
                                  name="c_p = %s" % fmt(vp, 4), quick=quick,
                                  analytic={} if base == "column" else None))

    # The nearly incompressible in-plane case again with a step below the
    # P-wave Courant limit, and with numerical damping.
    vp = p_wave_speed(BASES["inplane"]["cs"], 0.499)
    for name, extra in (("dt = 0.005 s", ["Time integration/Time step=0.005"]),
                        ("gamma = 0.6, beta = 0.3025", ["Time integration/Newmark gamma=0.6",
                                                        "Time integration/Newmark beta=0.3025"])):
        cases.append(Case("Poisson's ratio", "inplane", "implicit", "nu = 0.499",
                          ["Material/P-wave speed=%.10g" % vp] + extra,
                          name="c_p = %s, %s" % (fmt(vp, 4), name)))

    # An incompressible material cannot work (given by E and nu, since no
    # finite P-wave speed gives nu = 0.5).
    cases.append(Case("Poisson's ratio", "column", "implicit", "nu = 0.5",
                      ["Material/Parametrization=Young's modulus and Poisson's ratio",
                       "Material/Young's modulus=3", "Material/Poisson's ratio=0.5"],
                      name="E = 3"))

    # 6. Material contrast across the fault: the layer below y = 0 (the minus
    # side) has C times the elastic moduli, at the same density (wave speeds
    # times sqrt(C)); the penalties stay those of the base.
    for base, values in (("column", [1, 10, 100, 1000]),
                         ("inplane", [1, 10, 100, 1000])):
        b = BASES[base]
        for scheme in both:
            for c in values:
                r = math.sqrt(c)
                sets = [] if c == 1 else ["Scene/Box/Layer interfaces=0",
                        "Material/Names=top, bottom",
                        "Material/Density=%r, %r" % (b["rho"], b["rho"]),
                        "Material/S-wave speed=%.10g, %.10g" % (b["cs"], b["cs"] * r),
                        "Material/P-wave speed=%.10g, %.10g" % (b["cp"], b["cp"] * r)]
                quick = "ok" if (base, scheme, c) == ("column", "explicit", 1000) else None
                cases.append(Case("material contrast", base, scheme,
                                  "C = %g" % c, sets, quick=quick,
                                  analytic={"z_minus": b["rho"] * b["cs"] * r}
                                  if base == "column" else None))

    # The in-plane C = 1000 case again with smaller steps: does each method's
    # slip settle when only the time step changes?
    b = BASES["inplane"]
    r = math.sqrt(1000.0)
    contrast = ["Scene/Box/Layer interfaces=0", "Material/Names=top, bottom",
                "Material/Density=%r, %r" % (b["rho"], b["rho"]),
                "Material/S-wave speed=%.10g, %.10g" % (b["cs"], b["cs"] * r),
                "Material/P-wave speed=%.10g, %.10g" % (b["cp"], b["cp"] * r)]
    cases.append(Case("material contrast", "inplane", "implicit", "C = 1000",
                      contrast + ["Time integration/Time step=0.005"], name="dt = 0.005 s"))
    for fraction in (0.25, 0.125):
        cases.append(Case("material contrast", "inplane", "explicit", "C = 1000",
                          contrast + ["Time integration/Courant fraction=%g" % fraction],
                          name="%g dt_c" % fraction))

    # 7. Faults that open: zero or tensile normal traction.
    mode_one = ["Boundary conditions/Roller=west: x, east: x"]
    for scheme in both:
        cases.append(Case("opening", "column", scheme, "T_n = 0",
                          ["Fault/Initial traction=6.1; 0"],
                          name="shear column, zero strength",
                          analytic={"sigma": 0.0}))
        cases.append(Case("opening", "column", scheme, "T_n = +1",
                          ["Fault/Initial traction=6.1; 1"],
                          name="shear column, tension",
                          analytic={"sigma": 0.0}))
        cases.append(Case("opening", "column", scheme, "T_n = +1",
                          mode_one + ["Fault/Initial traction=0; 1"],
                          name="mode I column, absorbing ends"))
        cases.append(Case("opening", "column", scheme, "T_n = +1",
                          mode_one + ["Fault/Initial traction=0; 1",
                                      "Boundary conditions/Absorbing=",
                                      "Boundary conditions/Fixed=bottom, top"],
                          name="mode I column, fixed ends (gap opens and closes)",
                          end=10.0, quick="ok" if scheme == "explicit" else None))
        shear = "(abs(x) <= 1500) ? 81.6e6 : 70e6"
        cases.append(Case("opening", "inplane", scheme, "T_n = 0",
                          ["Fault/Initial traction=%s; 0" % shear],
                          name="whole fault"))
        cases.append(Case("opening", "inplane", scheme, "T_n = +10 MPa",
                          ["Fault/Initial traction=%s; 10e6" % shear],
                          name="whole fault in tension"))
        cases.append(Case("opening", "inplane", scheme, "T_n = +10 MPa",
                          ["Fault/Initial traction=70e6; (abs(x) <= 3000) ? 10e6 : -120e6"],
                          name="tensile patch abs(x) <= 3 km, 120 MPa compression elsewhere"))

    # 8. The rate-and-state family on the rate-and-state column.
    rs = "Fault/Rate and state/"
    for ab in (-0.02, -0.008, -0.004, 0.0, 0.004, 0.008):
        b = round(0.008 - ab, 10)
        for scheme in both:
            cases.append(Case("rate-and-state a - b", "rscolumn", scheme,
                              "a - b = %g" % ab,
                              [] if b == 0.012 else [rs + "Evolution effect=%r" % b],
                              name="b = %g" % b))
    for L in (1, 0.1, 1e-2, 1e-3, 1e-4, 1e-5):
        for scheme in both:
            cases.append(Case("rate-and-state L", "rscolumn", scheme, "L = %g" % L,
                              [] if L == 0.1 else [rs + "Characteristic slip distance=%r" % L]))
    for V in (1e-20, 1e-12, 1e-6, 1e-2, 1, 10):
        for scheme in both:
            cases.append(Case("rate-and-state initial slip rate", "rscolumn", scheme,
                              "V_ini = %g" % V,
                              [rs + "Initial state=", rs + "Initial slip rate=%r" % V]))
    for f in (0.1, 0.5, 1.0, 1.5, 3, 10):
        cases.append(Case("rate-and-state time step", "rscolumn", "explicit", "%g x dt_c" % f,
                          ["Time integration/Allow unstable time step=true"], dt_factor=f))
    for f in (0.1, 1, 10, 100, 1000):
        cases.append(Case("rate-and-state time step", "rscolumn", "implicit", "%g x dt_c" % f,
                          dt_factor=f))
    # Chester's law with frictional heating, from weak to very strong: a step
    # of the column (tau V about 6, dt = 0.01) warms the fault by about
    # 0.06 / H kelvin, against R T^2 / Q_A = 21 K that changes mu by A.
    chester = ["Fault/Friction law=chester", "Fault/Chester/Direct effect=0.008",
               "Fault/Chester/Evolution effect=0.012",
               "Fault/Chester/Characteristic slip distance=0.1",
               "Fault/Chester/Reference slip rate=1", "Fault/Chester/Initial state=0"]
    for H in (100, 1, 1e-2, 1e-3, 1e-4):
        for scheme in both:
            cases.append(Case("temperature", "rscolumn", scheme, "H = %g" % H,
                              chester + ["Fault/Chester/Heat capacity per area=%r" % H],
                              name="t_c = 1"))
    # Cochard-Madariaga weakening across the uniqueness limit: sigma_0 / V0
    # against the column's radiation impedance 1/2 (strength at rest 6).
    for ratio in (0.05, 0.25, 0.5, 1, 10, 1000):
        V0 = 1.0 / ratio
        for scheme in both:
            cases.append(Case("Cochard-Madariaga", "rscolumn", scheme,
                              "sigma_0 / V0 = %g" % ratio,
                              ["Fault/Friction law=cochard madariaga",
                               "Fault/Cochard Madariaga/Maximum traction drop=1",
                               "Fault/Cochard Madariaga/Residual strength=5",
                               "Fault/Cochard Madariaga/Reference slip rate=%r" % V0],
                              name="sigma_0 = 1, V0 = %g" % V0))

    # 11. Anisotropic rock (issue 39) on the in-plane base, both schemes:
    # transversely isotropic media whose slowest and fastest wave speeds
    # differ by a factor of 10, with the axis across and along the fault;
    # a strongly anisotropic orthotropic medium rotated 30 degrees in the
    # plane; a nearly singular tensor and one that couples in-plane and
    # out-of-plane motion, which the input checks must refuse.
    rho = BASES["inplane"]["rho"]
    mu = rho * BASES["inplane"]["cs"] ** 2
    lam = rho * BASES["inplane"]["cp"] ** 2 - 2 * mu
    ti = ["Material/Symmetry=transversely isotropic"]

    def constants(**c):
        return "Material/Stiffness=" + ", ".join(
            "%s = %.6e" % kv for kv in c.items())

    # Shear across the planes that contain the axis (C44) 300 times softer
    # than P along the axis: speeds sqrt(C11 / rho) / sqrt(C44 / rho) = 10.
    soft = constants(C11=lam + 2 * mu, C33=lam + 2 * mu, C13=lam,
                     C44=3 * mu / 100, C66=mu)
    for scheme in both:
        # (With the axis along the fault the in-plane tensor is the same
        # as with it across: C11 = C33, C12 = C13, and in-plane shear
        # involves the axis either way. At 45 degrees C16, C26 appear.)
        for axis, label in (("0, 1, 0", "axis across the fault"),
                            ("1, 1, 0", "axis at 45 degrees in the plane")):
            cases.append(Case("anisotropy", "inplane", scheme,
                              "TI, c_max / c_min = 10",
                              ti + [soft, "Material/Material axes=" + axis],
                              name=label))
        cases.append(Case(
            "anisotropy", "inplane", scheme, "orthotropic, 30 degrees",
            ["Material/Symmetry=orthotropic",
             constants(C11=4 * (lam + 2 * mu), C22=lam + 2 * mu,
                       C33=lam + 2 * mu, C12=lam, C13=lam, C23=lam,
                       C44=mu, C55=mu, C66=0.2 * mu),
             "Material/Material axes=0.866, 0.5, 0, -0.5, 0.866, 0"],
            name="C11 = 4 C22, C66 = mu / 5"))
    cases.append(Case("anisotropy", "inplane", "explicit", "nearly singular",
                      ti + [constants(C11=lam + 2 * mu, C33=lam + 2 * mu,
                                      C13=lam, C44=1e-9 * mu, C66=mu)],
                      name="C44 = 1e-9 mu"))
    cases.append(Case("anisotropy", "inplane", "explicit",
                      "no mirror plane",
                      ti + [soft, "Material/Material axes=1, 0, 1"],
                      name="axis out of the model plane"))
    # The same rock in 3-D, its axis oblique to every model axis (all 21
    # constants non-zero in the model's frame), on the 3-D patch; and the
    # nearly singular tensor there.
    for scheme in both:
        cases.append(Case("anisotropy", "patch3d", scheme,
                          "TI, c_max / c_min = 10",
                          ti + [soft, "Material/Material axes=1, 2, 3"],
                          name="axis (1, 2, 3)"))
    cases.append(Case("anisotropy", "patch3d", "implicit", "nearly singular",
                      ti + [constants(C11=lam + 2 * mu, C33=lam + 2 * mu,
                                      C13=lam, C44=1e-9 * mu, C66=mu),
                            "Material/Material axes=1, 2, 3"],
                      name="C44 = 1e-9 mu, axis (1, 2, 3)"))

    # 12. Anisotropic friction (issue 39) on the 3-D patch, both schemes:
    # friction ellipses of aspect ratio 1/20 to 20 (the strength along
    # e_2 = n x e_1 = -z is r times that along e_1 = x), the prestress at
    # 30 degrees from strike scaled so that its ellipse norm |A^-1 tau| is
    # the isotropic run's; and inputs the check must refuse: a ratio
    # outside [0.01, 100] and a first direction normal to the fault.
    for ratio in (0.05, 0.1, 0.5, 1, 2, 10, 20):
        scale = 1 / math.sqrt(0.75 + 0.25 / ratio ** 2)
        traction = ("((abs(x) <= 750 && abs(z) <= 750) ? 81.6e6 : 70e6) * "
                    "%.12g; -120e6; -((abs(x) <= 750 && abs(z) <= 750) ? "
                    "81.6e6 : 70e6) * %.12g" % (0.8660254 * scale,
                                                 0.5 * scale))
        for scheme in both:
            cases.append(Case("anisotropic friction", "patch3d", scheme,
                              "r = %g" % ratio,
                              ["Fault/Anisotropic friction/Strength ratio=%r"
                               % ratio,
                               "Fault/Anisotropic friction/First direction="
                               "1, 0, 0",
                               "Fault/Initial traction=" + traction],
                              name="ellipse norm of tau_0 70 MPa"))
    cases.append(Case("anisotropic friction", "patch3d", "explicit",
                      "r = 200", ["Fault/Anisotropic friction/Strength "
                                  "ratio=200"],
                      name="outside [0.01, 100]"))
    cases.append(Case("anisotropic friction", "patch3d", "implicit",
                      "e_1 normal to the fault",
                      ["Fault/Anisotropic friction/Strength ratio=2",
                       "Fault/Anisotropic friction/First direction=0, 1, 0"],
                      name="First direction = n"))
    # In 2-D the set is an interval: with the first direction normal to the
    # model plane the in-plane slip has the strength r S (the in-plane
    # base's prestress scaled by r, so that the ellipse norm is the
    # isotropic run's); a direction oblique to the plane is refused.
    for ratio in (0.05, 20):
        traction = ("((abs(x) <= 1500) ? 81.6e6 : 70e6) * %r; -120e6"
                    % ratio)
        for scheme in both:
            cases.append(Case("anisotropic friction", "inplane", scheme,
                              "2-D, r = %g" % ratio,
                              ["Fault/Anisotropic friction/Strength ratio=%r"
                               % ratio,
                               "Fault/Anisotropic friction/First direction="
                               "0, 0, 1",
                               "Fault/Initial traction=" + traction],
                              name="first direction normal to the plane"))
    cases.append(Case("anisotropic friction", "inplane", "explicit",
                      "2-D, oblique",
                      ["Fault/Anisotropic friction/Strength ratio=2",
                       "Fault/Anisotropic friction/First direction=1, 0, 1"],
                      name="First direction oblique to the plane"))

    # The in-plane explicit base, as a cheap check of the second base in --quick.
    for c in cases:
        if (c.family, c.base, c.scheme, c.value) == ("material contrast", "inplane", "explicit", "C = 1"):
            c.quick = "ok"
    return cases


FAMILIES = [
    ("penalty", "Penalty stiffness",
     "Normal and tangential penalty p_n = p_t as a multiple of the elastic "
     "stiffness of a fault-adjacent element, k_e = mu / h (20 Pa/m for the "
     "column, %s Pa/m for the in-plane base), from 1e-2 to 1e6, with the "
     "direct solver (MUMPS) and with the default iterative solver (GMRES + "
     "AMG), and p = 0, which the input check must refuse. Only the penalty "
     "method uses them."
     % fmt(BASES["inplane"]["k_element"])),
    ("slip-weakening distance", "Slip-weakening distance L_d",
     "L_d from 10 m down to 1e-4 m (the column is non-dimensional; its base "
     "value is 1, the in-plane base's 0.4 m). The slip-weakening slope "
     "(mu_0 - mu_d) |T_n| / L_d reaches 1e4 Pa/m in the column and 1.8e11 "
     "Pa/m in the in-plane base, against penalties of 1e5 and 5e11. A few "
     "implicit cases are repeated with softer penalties: the column at "
     "p = 1 k_e = 20 Pa/m, 500 times below the slope at L_d = 1e-4, and the "
     "in-plane base at p = 100 k_e. L_d = 0 must be refused."),
    ("strength drop", "Strength drop mu_0 - mu_d",
     "mu_d lowered from just below mu_0 (a drop of 1e-4) to a drop of 0.5, "
     "mu_0 fixed (0.6 in the column, 0.677 in the in-plane base); a negative "
     "drop (strengthening) must be refused."),
    ("time step", "Time step",
     "Time step as a multiple of the stable explicit step dt_c that the "
     "program prints for the base (dt_c = the bound from the element "
     "eigenvalues; the base explicit runs use 0.5 dt_c). Explicit runs above "
     "dt_c set `Allow unstable time step = true`, except one that shows the "
     "check. To give an instability time to grow, the end time is at least "
     "200 steps. (The implicit base steps, 0.01 and 0.02 s, are 0.49 and "
     "0.23 dt_c; they appear in the other families.) Stability is not "
     "accuracy: compare the in-plane slips at large steps with those of "
     "the base steps (the in-plane rows L_d = 0.4 m of the slip-weakening "
     "family, or C = 1 of the contrast family)."),
    ("Poisson's ratio", "Poisson's ratio",
     "Poisson's ratio up to 0.499 through the P-wave speed at fixed S-wave "
     "speed. In the column only the shear wave exists, so nu changes nothing "
     "but the stable explicit step; the in-plane base sees it fully. At "
     "nu = 0.499 (c_p = 77.5 km/s) the implicit step of the base, 0.02 s, is "
     "2.5 times the P-wave crossing time of a cell, so that case is also run "
     "with dt = 0.005 s and with numerical damping (gamma = 0.6, beta = "
     "0.3025, whose dissipation the energy balance counts as error). nu = 0.5, "
     "given by Young's modulus and Poisson's ratio, must be refused. The "
     "in-plane base is marginal (its nucleation patch barely exceeds the "
     "strength), so near nu = 0.5 whether the whole fault ruptures is "
     "sensitive: compare the undamped implicit run at dt = 0.02 s with the "
     "same case at dt = 0.005 s, damped, and explicit. Average-acceleration "
     "Newmark does not damp the P waves it cannot resolve, and with a step "
     "above their crossing time their error can push fault nodes over "
     "their strength: resolve the P-wave crossing time or add numerical "
     "damping."),
    ("material contrast", "Material contrast across the fault",
     "The layer below the fault (y < 0, the minus side) has C times the "
     "elastic moduli of the layer above, at the same density (its wave "
     "speeds are sqrt(C) times higher), C up to 1000 (`Scene/Box/Layer "
     "interfaces = 0` and two-entry lists in `Material`; C = 1 is the base "
     "without layers). The penalties stay "
     "those of the base, so against the stiff side's element they are C "
     "times weaker. The in-plane C = 1000 case is also run with smaller "
     "steps (implicit dt = 0.005 s; explicit 0.25 and 0.125 dt_c instead of "
     "0.5 dt_c), to see whether each method's slip settles as the step "
     "shrinks. On an interface between such different materials slip "
     "changes the normal stress, and Coulomb friction with an instantaneous "
     "response to it is known to be ill-posed there (Adams 1995; Ranjith and "
     "Rice 2001): the answer can then depend on the discretisation, and only "
     "a regularised normal-stress response (Prakash-Clifton) would make it "
     "converge. Where the two methods disagree, the summary says so."),
    ("opening", "Faults that open",
     "Zero or tensile normal traction in `Fault/Initial traction`. In the "
     "shear column u_y is held, so the fault cannot move apart: a tensile "
     "traction only frees it (zero strength). The mode I columns hold u_x "
     "instead, so the two halves separate; with fixed instead of absorbing "
     "ends the reflected waves bring them back together repeatedly. In the "
     "in-plane base the whole fault, or a 6 km patch, starts at zero or "
     "tensile normal traction."),
    ("rate-and-state a - b", "Rate-and-state: a - b",
     "The rate-and-state column (base **rscolumn**): regularised aging law with "
     "a = 0.008, L = 0.1, f0 = 0.6, V0 = 1, theta(0) = 1, tau_0 = 6.5, "
     "sigma_n = 10, so that the slip rate rises from about 0.55 to the steady "
     "state. b from 0.028 (a - b = -0.02, strongly velocity weakening) to 0 "
     "(a - b = 0.008, strengthening)."),
    ("rate-and-state L", "Rate-and-state: characteristic slip distance L",
     "L from 1 down to 1e-5 on the rate-and-state column (base 0.1): the "
     "state relaxes over V dt / L, up to 1e3 per step."),
    ("rate-and-state initial slip rate", "Rate-and-state: initial slip rate",
     "The initial state computed from the traction ratio 0.65 at V_ini, from "
     "1e-20 to 10 m/s (the state then spans some 40 decades)."),
    ("rate-and-state time step", "Rate-and-state: time step",
     "Time steps from far below to far above the stable explicit step dt_c "
     "of the column, with the rate-and-state column."),
    ("temperature", "Temperature (Chester's law) with strong heating",
     "Chester's law on the rate-and-state column (A = 0.008, B = 0.012, "
     "d_c = 0.1, V_c = 1, theta(0) = 0, T* = T_r = T(0) = 573 K, "
     "Q_A = Q_B = 1.3e5 J/mol, t_c = 1): the heat capacity per area H from "
     "100 (a step warms the fault by 6e-4 K) to 1e-4 (by some 600 K, far "
     "beyond the 21 K that change mu by A)."),
    ("Cochard-Madariaga", "Cochard-Madariaga rate weakening",
     "Strength 5 + V0 / (V0 + V) on the rate-and-state column (tau_0 = 6.5 "
     "above the strength at rest, 6): the largest weakening rate sigma_0 / V0 "
     "from 0.05 to 1000, against the radiation impedance of the column, 1/2. "
     "The law's check refuses sigma_0 / V0 above the node's impedance."),
    ("anisotropy", "Anisotropic rock",
     "The in-plane base in transversely isotropic rock whose wave speeds "
     "span a factor of 10 (C44 = 0.03 mu, the other constants the "
     "isotropic rock's), with the symmetry axis across the fault and at 45 "
     "degrees to it in the model plane; an orthotropic rock with C11 = 4 C22 and C66 = mu / 5 rotated "
     "30 degrees in the model plane; and two tensors the input check must "
     "refuse: a nearly singular one (C44 = 1e-9 mu) and one whose axis "
     "leaves the model plane, which couples in-plane and out-of-plane "
     "motion. In 3-D the same transversely isotropic rock with its axis "
     "along (1, 2, 3), oblique to every model axis (all 21 constants "
     "non-zero in the model's frame), on the 3-D miniature of TPV3 of the "
     "anisotropic-friction family, and the nearly singular tensor there."),
    ("anisotropic friction", "Anisotropic friction",
     "A 3-D miniature of TPV3 (500 m cells, the fault 4 x 3 km, the "
     "prestress 30 degrees from strike) with friction ellipses of aspect "
     "ratio r from 1/20 to 20 (the strength along dip r times that along "
     "strike), the prestress scaled so that its ellipse norm |A^-1 tau_0| "
     "stays 70 MPa (81.6 MPa in the patch); implicit Newmark with penalty "
     "contact and the explicit scheme with split nodes. With r < 1 the slip "
     "turns towards dip, where the strength drop is r times smaller and the "
     "law's slip |A du| r times shorter than the slip: the weakening per "
     "unit slip falls as r^2, so that at r = 0.1 and 0.05 the patch is far "
     "too small to nucleate and the fault creeps by a millimetre or two "
     "(as it must). A ratio outside [0.01, 100] and a first direction "
     "normal to the fault must be refused. In 2-D, where the set is an "
     "interval, the in-plane base with the first direction normal to the "
     "model plane (the in-plane slip along the second axis: strength r S) "
     "and its prestress times r, at r = 0.05 and 20, and a first direction "
     "oblique to the model plane, which must be refused."),
]


# ---------------------------------------------------------------------------
# The 1-D analytic slip of the column.

def analytic_slip(t, tau0, sigma, mu_s, mu_d, dc, z_plus, z_minus):
    """Slip of the 1-D slip-weakening interface between two half-spaces of
    impedance z_plus and z_minus: eta V = tau_0 - strength(s), with
    eta = 1 / (1 / z_plus + 1 / z_minus), from rest (tau_0 above the static
    strength)."""
    eta = 1.0 / (1.0 / z_plus + 1.0 / z_minus)
    a = tau0 - sigma * mu_s            # excess stress at the start
    w = sigma * (mu_s - mu_d) / dc     # slope of the strength drop
    if a <= 0:
        return 0.0
    if w <= 0:
        return a * t / eta
    tw = eta / w * math.log(1 + w * dc / a)
    if t <= tw:
        return a / w * math.expm1(w * t / eta)
    return dc + (tau0 - sigma * mu_d) / eta * (t - tw)
