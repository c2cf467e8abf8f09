// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

/*!
\ingroup PkgSurfaceMeshSeamOptimizationConcepts
\cgalConcept

The concept `DistortionEnergy` describes the per-triangle distortion density
minimized by the optimizer. It is a function \f$\psi(J)\f$ of the 2x2
Jacobian \f$J\f$ of the affine map from a triangle of the 3D mesh (expressed
in a 2D orthonormal frame of its plane) to its UV triangle:
\f$ J = [u_1 - u_0,\ u_2 - u_0]\, D_m^{-1} \f$, where the columns of
\f$D_m\f$ are the rest triangle's edge vectors in that frame. The optimizer
minimizes the area-weighted mean
\f$ E = \sum_t A_t\, \psi(J_t) / \sum_t A_t \f$
and obtains gradients and Hessians with respect to the UV coordinates from
\f$\partial\psi/\partial J\f$ and \f$\partial^2\psi/\partial J^2\f$ by the
chain rule, so a model works at the level of \f$J\f$ only.

The energy must be finite for \f$\det(J) > 0\f$ and return
\f$+\infty\f$ for \f$\det(J) \le 0\f$ (flipped or degenerate triangle). The
optimizer's line search never accepts a step that makes a UV triangle's signed
area non-positive, so gradients and Hessians are only requested where
\f$\det(J) > 0\f$.

Matrices in \f$J\f$-space are flattened column-major:
vec(J) = (J(0,0), J(1,0), J(0,1), J(1,1)), the storage order of `Eigen::Matrix2d`.

A model is default constructible, copy constructible and copy assignable:
it is passed by value (named parameter `energy`), and
`CGAL::Surface_mesh_seam_optimization::Seam_optimizer` holds
a default-constructed one until it assigns the given one.

The models of the package are isotropic (\f$\psi\f$ depends on the singular
values \f$\sigma_1, \sigma_2\f$ of \f$J\f$ only) and project their Hessians
through a closed-form eigensystem; a user model may compute its Hessian in any
way that meets the requirements below.

\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Symmetric_Dirichlet_energy`
\cgalHasModel `CGAL::Surface_mesh_seam_optimization::ARAP_energy`
\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Conformal_energy`
*/
class DistortionEnergy
{
public:
  /// \name Operations
  /// All operations are `const` and must be safe to call concurrently for
  /// different triangles.
  /// @{

  /*!
  returns \f$\psi(J)\f$, or \f$+\infty\f$ if \f$\det(J) \le 0\f$.
  */
  double value(const Eigen::Matrix2d& J) const;

  /*!
  returns \f$\psi(J)\f$ (the same figure as `value(J)`) and writes
  \f$\partial\psi/\partial J\f$ into `dJ`.
  */
  double value_and_gradient(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ) const;

  /*!
  returns \f$\psi(J)\f$ (the same figure as `value(J)`), writes
  \f$\partial\psi/\partial J\f$ into `dJ` and the symmetric 4x4 Hessian
  \f$\partial^2\psi/\partial\,\mathrm{vec}(J)^2\f$ into `H`.
  If `project` is `true`, `H` is made positive semi-definite by setting its
  negative eigenvalues to zero (eigenvectors unchanged), so that the assembled
  Newton system is positive semi-definite; if `false`, `H` is the exact
  Hessian.
  */
  double value_gradient_and_hessian(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ,
                                    Eigen::Matrix4d& H, bool project = true) const;

  /*!
  returns the minimum of \f$\psi\f$ over all \f$J\f$ (its value at rotations
  for the models of the package), so that \f$E\f$ minus this value measures
  the distortion above the ideal.
  */
  static constexpr double minimum_value();

  /*!
  optional: `true` for an energy that does not change when the map is scaled
  uniformly (`Conformal_energy` with `area_weight` 0). Its map is then written
  at the uniform scale that minimizes E_SD. An energy without this member is
  taken as not scale invariant.
  */
  bool is_scale_invariant() const;

  /*!
  optional: the distortion bound of `optimize_seams()` when none is given,
  in the energy's own units, above `minimum_value()`. Without it,
  `distortion_bound` must be given (else `ERROR_WRONG_PARAMETER`).
  */
  double default_bound() const;

  /*!
  returns a short lowercase identifier of the energy for logs and output
  (`"symmetric_dirichlet"`, `"arap"`, `"conformal"` for the models of the package).
  */
  const char* name() const;

  /// @}
};
