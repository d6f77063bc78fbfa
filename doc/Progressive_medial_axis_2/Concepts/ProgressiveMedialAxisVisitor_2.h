/*!
\ingroup PkgProgressiveMedialAxis2Concepts
\cgalConcept

A visitor of `CGAL::Progressive_medial_axis_2`: it is told of every critical
point of every merge, of every merge and of every refinement step, as they
happen.  Timings and per-step figures (the queue size \f$ n_v \f$ of every
step, as in the paper's Figs. 17 and 20) are collected by a visitor; the
statistics of the progressive object keep only totals.

A visitor is passed by reference to `refine(visitor)` and
`refine_all(visitor)`.  Its functions are called in the thread that refines,
synchronously, and should be cheap: they run inside the merge.

\cgalHasModel `CGAL::Default_progressive_medial_axis_visitor` (does nothing; derive from it
to define only some of the functions)
*/
class ProgressiveMedialAxisVisitor_2 {
public:
  /// Called at every switch point of a merge: the retracting tip passed the
  /// foot of a vertex of one of the two cells of the separator.
  void on_switch();
  /// Called at every vanishing point of a merge: a generator left the list
  /// of the tip's cell and a branch point was created.
  void on_vanish();
  /// Called after every merge (several per step when a triangle shares
  /// several edges with the grown shape), with what it did.
  void on_merge(const CGAL::Progressive_medial_axes::Merge_statistics& m);
  /// Called after every refinement step, with its number (1 for the first
  /// merge) and the largest queue size \f$ n_v \f$ of its merges.
  void on_step(std::size_t step, std::size_t n_v);
};
