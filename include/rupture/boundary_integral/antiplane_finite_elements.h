#ifndef rupture_boundary_integral_antiplane_finite_elements_h
#define rupture_boundary_integral_antiplane_finite_elements_h

#include <rupture/boundary_integral/stiffness.h>

#include <deal.II/base/mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    struct AntiplaneBody;

    /**
     * The fault's stiffness from a finite-element model of the body: the
     * antiplane problem of AntiplaneHalfSpace (a vertical strike-slip fault
     * at x = 0 from the free surface down, mu Delta u = 0 for the
     * out-of-plane displacement u), with the body meshed instead of
     * solved in closed form. By the antisymmetry of the problem only the
     * side x > 0 is meshed, where u = s / 2 on the fault: a box of the
     * given size whose cells have the given size at the fault down to W
     * and grow by a constant factor away from it (in x, and in depth below
     * W), with FE_Q elements of the given degree (Gauss-Lobatto nodes).
     *
     * The elements of the fault are its nodes from the surface down to
     * (not including) W, each standing for its tributary length w_i (the
     * integral of its shape function along the fault). Everything else is
     * held: the fault below W and the far sides (x = L, y = -L) at the
     * plate's motion, so that only the slip relative to a fault slipping
     * uniformly all the way down makes stress, as in the half-space; the
     * surface y = 0 is free. Column j of K is the traction change of a unit
     * slip at node j (u = 1/2 there, 0 at the other held nodes): the
     * traction at node i is the reaction of the solved field there
     * divided by w_i, tau_i = -(A u)_i / w_i (the variationally consistent
     * flux, A the stiffness matrix of the body). One sparse direct
     * factorisation serves all columns; the ranks share the columns and
     * exchange them.
     */
    class AntiplaneFiniteElements : public Stiffness
    {
    public:
      struct Settings
      {
        /// W (m): the fault solved down to here.
        double fault_depth = 40e3;
        /// The node spacing (m) along the fault above W: the cells there
        /// are degree times as long.
        double node_spacing = 100;
        /// The polynomial degree of the elements (1 to 4; checked).
        int degree = 2;
        /// L (m): the width and the depth of the box.
        double domain_size = 400e3;
        /// The ratio of neighbouring cells' sizes away from the fault.
        double growth = 1.1;
        /// The antiplane shear moduli (Pa): C55 = mu, the stress sigma_xz
        /// across the fault per u,x, and C44, sigma_yz per u,y (0: C55,
        /// isotropic). An anisotropic body whose model plane is a plane of
        /// mirror symmetry and C45 = 0: C55 u,xx + C44 u,yy = 0.
        double shear_modulus = 1, vertical_shear_modulus = 0;
        /// Whether to keep the meshed body after the stiffness is
        /// computed (body(): the fully dynamic phases need it; otherwise
        /// its memory is freed).
        bool keep_body = false;
      };

      /// Mesh, factorise and solve (collective). Throws on settings out of
      /// range, naming the <Boundary integral> entries.
      AntiplaneFiniteElements(const Settings &settings,
                              const MPI_Comm  communicator);

      unsigned int
      size() const override
      {
        return node_depths.size();
      }

      double
      depth(const unsigned int i) const override
      {
        return node_depths[i];
      }

      double
      length(const unsigned int i) const override
      {
        return tributary[i];
      }

      double
      extent() const override
      {
        return settings.fault_depth;
      }

      double
      shear_modulus() const override
      {
        return settings.shear_modulus;
      }

      std::vector<double>
      rows(const unsigned int begin, const unsigned int end) const override;

      std::string
      description() const override;

      /// The meshed body (for the fully dynamic phases), if
      /// Settings::keep_body; null otherwise.
      std::shared_ptr<const AntiplaneBody>
      body() const
      {
        return body_;
      }

    private:
      const Settings                       settings;
      std::shared_ptr<const AntiplaneBody> body_;
      /// The number of cells and of unknowns of the mesh.
      unsigned int        n_cells = 0, n_dofs = 0;
      std::vector<double> node_depths, tributary;
      /// K, row by row (N x N).
      std::vector<double> matrix;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
