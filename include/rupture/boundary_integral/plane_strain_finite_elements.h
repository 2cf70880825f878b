#ifndef rupture_boundary_integral_plane_strain_finite_elements_h
#define rupture_boundary_integral_plane_strain_finite_elements_h

#include <rupture/boundary_integral/stiffness.h>

#include <deal.II/base/mpi.h>

#include <array>
#include <string>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * The fault's stiffness from a finite-element model of a plane-strain
     * body (SCEC SEAS BP3): a planar fault that dips at an angle delta from
     * the free surface y = 0, starting at x = 0 and running down towards
     * x > 0, in a homogeneous isotropic half-space (Lame constants lambda,
     * mu), the in-plane displacement (u_x, u_y) solved with FESystem of
     * FE_Q of the given degree (Gauss-Lobatto nodes) on both sides.
     *
     * The mesh is a grid of parallelograms: lines parallel to the fault,
     * and horizontal lines. Along the fault, down to the distance W, the
     * cells are degree times the node spacing long (and as wide across);
     * they grow by a constant factor away from the fault and below W, to a
     * box that reaches the distance L to either side of the fault and the
     * depth L. Its vertices on the fault above W are doubled, so the two
     * sides meet only below W: the block above the fault (x larger at a
     * given depth, the hanging wall) and the one below (the footwall).
     *
     * The elements of the fault are its node pairs from the surface down to
     * (not including) W, each standing for its tributary length w_i. The
     * slip s_j of pair j is the hanging wall's displacement relative to the
     * footwall along the slip direction d (up the dip for a thrust fault,
     * down it for a normal fault); the sides do not open. The far sides and
     * the bottom are held, so only the slip relative to a fault slipping
     * uniformly all the way down (the two blocks moving rigidly) makes
     * stress, as in the half-space. Column j of K is the traction a unit
     * slip at pair j makes on the footwall: with u the solved field,
     * T_i = (A u)_i / w_i at the footwall's node i (A the stiffness matrix,
     * the hanging wall's node tied to it: u_hw = u_fw + s d), the shear
     * traction along d, tau_i = T_i . d, and the change of the normal
     * stress (compression > 0), -T_i . n, n the normal from the footwall
     * into the hanging wall. One sparse direct factorisation serves all
     * columns; the ranks share the columns and exchange them.
     */
    class PlaneStrainFiniteElements : public Stiffness
    {
    public:
      struct Settings
      {
        /// W (m): the fault solved down to this distance along the dip.
        double fault_extent = 40e3;
        /// The node spacing (m) along the fault above W.
        double node_spacing = 100;
        /// The polynomial degree of the elements (1 to 4; checked).
        int degree = 2;
        /// L (m): the distance of the far sides from the fault, and the
        /// depth of the box.
        double domain_size = 400e3;
        /// The ratio of neighbouring cells' sizes away from the fault.
        double growth = 1.1;
        /// The dip (degrees, 10 to 90).
        double dip = 90;
        /// Thrust (the hanging wall moves up the dip) or normal faulting.
        bool thrust = true;
        /// The Lame constants (Pa).
        double shear_modulus = 1, lambda = 1;
        /// The x (m) of points on the surface whose motion is wanted
        /// (surface_motion(); x <= 0 on the footwall, x > 0 on the hanging
        /// wall; at most the box's reach).
        std::vector<double> surface_points;
      };

      /// Mesh, factorise and solve (collective). Throws on settings out of
      /// range, naming the <Boundary integral> entries.
      PlaneStrainFiniteElements(const Settings &settings,
                                const MPI_Comm  communicator);

      unsigned int
      size() const override
      {
        return node_distances.size();
      }

      double
      depth(const unsigned int i) const override
      {
        return node_distances[i];
      }

      double
      length(const unsigned int i) const override
      {
        return tributary[i];
      }

      double
      extent() const override
      {
        return settings.fault_extent;
      }

      double
      shear_modulus() const override
      {
        return settings.shear_modulus;
      }

      double
      dip() const override
      {
        return settings.dip;
      }

      std::vector<double>
      rows(const unsigned int begin, const unsigned int end) const override;

      bool
      changes_normal_stress() const override
      {
        return true;
      }

      std::vector<double>
      normal_rows(const unsigned int begin,
                  const unsigned int end) const override;

      unsigned int
      n_surface_points() const override
      {
        return settings.surface_points.size();
      }

      std::array<double, 2>
      surface_motion(const unsigned int         k,
                     const std::vector<double> &fault_values,
                     const double               plate_value) const override;

      std::string
      description() const override;

    private:
      const Settings settings;
      /// The number of cells and of unknowns of the mesh.
      unsigned int        n_cells = 0, n_dofs = 0;
      std::vector<double> node_distances, tributary;
      /// K and the normal stiffness, row by row (N x N each).
      std::vector<double> shear, normal;
      /// The surface points' displacements per unit slip: for point k and
      /// component c, the N values at 2 N k + N c.
      std::vector<double> surface;
      /// The slip direction (the hanging wall's relative to the
      /// footwall).
      std::array<double, 2> direction = {{0, 0}};
      /// +1 for a surface point on the hanging wall, -1 on the footwall.
      std::vector<double> side_of_point;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
