/*!
\ingroup PkgProgressiveMedialAxis2Concepts
\cgalConcept

The concept `ProgressiveMedialAxisTraits_2` holds every numeric decision and
construction of the topology-oriented merge of `CGAL::Progressive_medial_axis_2`.
The merge itself is purely topological: it asks the traits only

- for the orientation of three input points (the corners of the merged shape),
- for the position along a separator of its events (switch and vanishing
  critical points) and for their order,
- for the disk tangent to three generators (the branch points).

A *site* is a generator: a point (a reflex vertex of the polygon), or an
open segment with the shape on its left.  A *separator* is a segment
`line` from `P` to `Q`; its event times are positions along it, with `P` at
time 0.  The time of a vanishing point of the site `b` between `a` and `d`
is where the separator's retracting tip meets the disk tangent to `a, b, d`;
the time of a switch point is the foot on the separator of a vertex of the
cell of one of its sides.

Whatever the number type, the merge keeps a valid topology; with exact
decisions (`Has_exact_decisions`), the topology is that of the exact medial
axis.

\cgalHasModel `CGAL::Progressive_medial_axis_traits_2<K>`
*/
class ProgressiveMedialAxisTraits_2 {
public:
  /// \name Types
  /// @{

  /// A model of `Kernel`: the kernel of the points and of the result,
  /// `CGAL::Medial_axis_2<Kernel>`.
  typedef unspecified_type Kernel;
  /// Number type of the radii of constructed disks.
  typedef unspecified_type FT;
  /// Type of input points and of constructed branch points.
  typedef unspecified_type Point_2;
  /// A generator: `Site_2::point(p)` or `Site_2::segment(p, q)`, with
  /// members `is_point`, `p`, `q` and equality.
  typedef unspecified_type Site_2;
  /// The position of an event along a separator; copyable.
  typedef unspecified_type Event_time_2;
  /// `Orientation operator()(Point_2 p, Point_2 q, Point_2 r)`, exact on input points.
  typedef unspecified_type Orientation_2;

  /// A function object: `Event_time_2 operator()(Site_2 line)`, the time of the source of the separator.
  typedef unspecified_type Compute_start_time_2;
  /// A function object: `Event_time_2 operator()(Site_2 line)`, the time of the target of the separator.
  typedef unspecified_type Compute_end_time_2;
  /// A function object: `bool operator()(Site_2 line, Site_2 c, Site_2 a, Site_2 b, Event_time_2& t)`:
  /// the time along `line` of the foot of the disk tangent to `c, a, b` (in
  /// counter-clockwise order around its centre), where `c` is `line` or its
  /// reverse; false if the disk cannot be built.
  typedef unspecified_type Compute_switch_time_2;
  /// A function object: `Event_time_2 operator()(Site_2 line, Point_2 p)`: the time of the foot of `p`.
  typedef unspecified_type Compute_foot_time_2;
  /// A function object: `bool operator()(Site_2 line, Site_2 a, Site_2 b, Site_2 d, Event_time_2& t)`:
  /// the vanishing time of `b`; false if the disk tangent to `a, b, d` in
  /// counter-clockwise order does not exist, does not touch the segments
  /// themselves, or misses the line.
  typedef unspecified_type Compute_vanishing_time_2;
  /// A function object: `Comparison_result operator()(Event_time_2, Event_time_2)`; a total order.
  typedef unspecified_type Compare_event_time_2;
  /// A function object: `bool operator()(Event_time_2 t, Event_time_2 now, Site_2 line)`:
  /// whether an event at `t` is already in the past at time `now`.
  typedef unspecified_type Is_event_in_past_2;
  /// A function object: `bool operator()(Site_2 a, Site_2 b, Site_2 c, Point_2& centre, FT& radius)`:
  /// the disk tangent to three sites whose cells meet at its centre in this
  /// counter-clockwise order; false if there is none.
  typedef unspecified_type Construct_medial_disk_2;
  /// A function object: `bool operator()(Site_2 a0, Site_2 a1, Site_2 a2, Site_2 b0, Site_2 b1, Site_2 b2)`:
  /// whether the disks tangent to `a0, a1, a2` and to `b0, b1, b2` are the
  /// same disk (two vertices of the axis at one point, where four or more
  /// generators meet).
  typedef unspecified_type Equal_medial_disks_2;
  /// A function object: `bool operator()(Site_2 line, Site_2 a, Site_2 b, Site_2 c, Event_time_2& t)`:
  /// the time along the segment `line` of the foot of the centre of the disk
  /// tangent to `a, b, c` (counter-clockwise around its centre), a disk that
  /// need not touch `line`; false if there is none (boundary evolution).
  typedef unspecified_type Compute_disk_foot_time_2;
  /// A function object: `bool operator()(Site_2 a, Site_2 b, Site_2 c, Site_2 s)`:
  /// whether the open disk tangent to `a, b, c` (counter-clockwise; it must
  /// exist) meets the closed segment `s` (boundary evolution: a vertex in
  /// conflict with a new edge).
  typedef unspecified_type Do_intersect_disk_segment_2;

  /// @}

  /// \name Optional: the centre of a disk kept with its vertex
  /// A model may also provide a type `Disk_hint`, an enclosure of the centre
  /// of a medial disk, with a member `bool valid`, a member function
  /// `bool to_doubles(double& x, double& y, double& err) const` (the centre
  /// lies within `err` of `(x, y)` in each coordinate; false where they are
  /// not finite) and a static member
  /// function `Disk_hint from_doubles(double x, double y, double err)`; and
  /// the overloads
  /// `bool Compute_vanishing_time_2::operator()(Site_2 line, Site_2 a, Site_2 b, Site_2 d, Event_time_2& t, Disk_hint& h)`,
  /// which also sets `h` to an enclosure of the centre of the disk tangent
  /// to `a, b, d` or leaves it invalid, and
  /// `bool Compute_switch_time_2::operator()(Site_2 line, Site_2 c, Site_2 a, Site_2 b, Event_time_2& t, const Disk_hint& h)`,
  /// where `h`, if valid, encloses the centre of the disk tangent to `c, a,
  /// b`.  Where `FT` is a floating-point type, the merge then keeps the
  /// centre of the disk of each vanishing event with the vertex the event
  /// makes, until the vertex's disk is constructed, and computes the switch
  /// times at that vertex from it.  `CGAL::Progressive_medial_axis_traits_2<K>`
  /// provides them for filtering kernels (`CGAL::Epick`).
  /// @{
  /// @}

  /// Whether the event decisions are exact.
  static constexpr bool Has_exact_decisions = unspecified;

  /// \name Access to the function objects
  /// @{
  Orientation_2 orientation_2_object() const;
  Compute_start_time_2 compute_start_time_2_object() const;
  Compute_end_time_2 compute_end_time_2_object() const;
  Compute_switch_time_2 compute_switch_time_2_object() const;
  Compute_foot_time_2 compute_foot_time_2_object() const;
  Compute_vanishing_time_2 compute_vanishing_time_2_object() const;
  Compare_event_time_2 compare_event_time_2_object() const;
  Is_event_in_past_2 is_event_in_past_2_object() const;
  Construct_medial_disk_2 construct_medial_disk_2_object() const;
  Equal_medial_disks_2 equal_medial_disks_2_object() const;
  Compute_disk_foot_time_2 compute_disk_foot_time_2_object() const;
  Do_intersect_disk_segment_2 do_intersect_disk_segment_2_object() const;
  /// @}
};
