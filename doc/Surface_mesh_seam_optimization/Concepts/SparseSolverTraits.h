/*!
\ingroup PkgSurfaceMeshSeamOptimizationConcepts
\cgalConcept

The concept `SparseSolverTraits` describes the sparse direct solver that the
projected Newton iterations of the package use to solve \f$ H p = -g \f$,
where \f$ H \f$ is the assembled Hessian of the distortion energy (each
triangle's contribution projected to be positive semi-definite) and \f$ g \f$
its gradient.

The work is split in three steps so that the symbolic analysis (fill-reducing
ordering, elimination tree) is done once per sparsity pattern and reused by
every Newton iteration until the UV topology changes:
`analyze_pattern()` when the pattern is new, `factorize()` when the Hessian
changed too much since the last factorization, then `solve()` with one or
more right-hand sides. Between two factorizations, the Newton step is found
by conjugate gradients preconditioned by `solve()` with the last
factorization (of an earlier Hessian of the same pattern): `solve()` must
keep using that factorization, whatever became of the matrix it was
computed from.

The matrix is symmetric and only its lower triangle (row index >= column
index, diagonal included) is stored: a model must read that triangle, as
Eigen's `SimplicialLDLT<Matrix, Eigen::Lower>` does.

A model is default constructible and copy constructible; it is passed by
value, like CGAL's own solver traits, so a copy may share the factorization
with the original.

A model may also eliminate the matrix's 2x2 blocks (one per UV vertex) in an
order it is given, as `Default_sparse_solver_traits` does: with the members
`bool analyze_pattern(const Matrix& A, const std::vector<int>& block_ordering)`
and `const std::vector<int>& block_ordering() const` (the order of the last
analysis, empty if it has none), the Newton iterations keep the order of an
analysis for the next few patterns after topology operations instead of
computing a new fill-reducing ordering for each.

\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Default_sparse_solver_traits` (the default)
\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Eigen_simplicial_ldlt_traits`
\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Cholmod_traits` (when SuiteSparse is found)
\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Eigen_sparse_solver_traits` with any Eigen sparse direct solver

\sa `CGAL::Surface_mesh_seam_optimization::minimize_distortion()`
*/
class SparseSolverTraits
{
public:
  /// \name Types
  /// @{

  /// The sparse matrix type: column-major, `double`, `int` indices.
  typedef Eigen::SparseMatrix<double> Matrix;

  /// @}

  /// \name Creation
  /// @{

  /// Default constructor.
  SparseSolverTraits();

  /// @}

  /// \name Operations
  /// @{

  /// Symbolic analysis of the sparsity pattern of `A` (a symmetric matrix of
  /// which at least the lower triangle is stored). Called again only when the
  /// pattern changes. Returns `false` on failure.
  bool analyze_pattern(const Matrix& A);

  /// Numeric factorization of `A`, which has the pattern given to the last
  /// call of `analyze_pattern()`. Returns `false` on failure (for example a
  /// matrix that is not numerically positive definite).
  bool factorize(const Matrix& A);

  /// Solves `A x = b` with the last factorization. Returns `false` on failure,
  /// including when `x` is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  /// @}
};
