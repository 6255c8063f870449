!> The active particles gathered in cell order (contiguous per cell), the layout every pair
!> traversal works on; rates are accumulated here and scattered back afterwards.
!>
!> Image particles (axisymmetric mode and periodic z; sph_params_t%geometry%kind, %periodic_z):
!> gather_sorted then adds, as extra sorted slots, the mirror image of every active particle
!> within 2h + skin of the axis x = 0 at the build (x -> -x, u -> -u, the rest equal) and the
!> periodic image of every particle or axis image within 2h + skin of z = domain%zmin or
!> domain%zmax at the build (z -+ lz). An image slot has grid%order(k) > st%n, src(k) its source
!> particle, usign(k) its x (and u) sign and zshift(k) its z shift, fixed at the build; at
!> every gather it is put at (usign x, z + zshift) of its source's current position. The
!> pair sums treat it as any neighbour and what accumulates in its slot is discarded: every
!> real particle sees each of its neighbours, real or image, once. Pairs of two images are
!> therefore not listed. In axisymmetric mode m holds the planar mass m / (2 pi r)
!> (physics/axisymmetric.f90), so that every pair loop is the SPH of the meridian plane.
!>
!> gather_sorted is also the one place that decides the neighbour list
!> (neighbours/verlet_list.f90): the particles are sorted, and the pairs closer than
!> 2h + skin listed, at their positions at the last build (xb, zb); between builds the sorted
!> order and the list are kept and only the fields are gathered again. The list is built again
!> when a particle has moved more than skin/2 from xb, zb, or the active set has changed.
!>
!> Kill -9 + resume stays bitwise: the pair order depends only on the build positions, and
!> those live in the caller's arrays list_x, list_z (state_t), which a checkpoint keeps. A
!> resumed run (or any call whose list_x, list_z differ from the work space's) sorts and lists
!> from them again and gets the same order; the decision to build depends only on x, z,
!> list_x, list_z and the active flags. Without those arrays the work space keeps its own
!> copy (tests, diagnostics). list_x = NaN means "no list": build from the current positions.
!>
!> With image particles the list is kept over steps in the same way (update_list decides on
!> the real particles alone, and builds the images from their build positions). It stays
!> exact. A reflection and a shift by lz are isometries, so an image slot has moved exactly
!> as far from its build position as its source: every slot, real or image, is within
!> skin/2 of where it was at the build. (a) The images exist: a particle within 2h of the
!> axis (of a z end) now, whose image a real particle may see within 2h (the real particles
!> lie at x >= 0 but for a move across the axis within a step, before its fold), was within
!> 2h + skin/2 of it at the build, so its image was made then (and the periodic image of its
!> axis image with it); the images the build made beyond 2h of the axis or end now are more
!> than 2h from every real particle and add no pair. (b) Their pairs are listed: two slots
!> within 2h now were within 2h + skin at the build. A wrap through a periodic end moves a
!> particle by lz, and the next gather builds again; a fold across the axis moves it by
!> 2|x|, which the same test measures. The build positions of the images follow from those
!> of the particles (list_x, list_z), so kill -9 + resume stays bitwise here too.
module sorted_state
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use sphjet_kinds, only: rp, ip, KIND_FLUID, GEOM_AXISYMMETRIC
  use sphjet_types, only: state_t, sph_params_t
  use axisymmetric, only: planar_mass
  use cell_list, only: cell_grid_t, build_cell_list
  use pair_list, only: pair_list_t
  use verlet_list, only: row_list_t, build_verlet_rows
  !$ use omp_lib, only: omp_get_max_threads, omp_in_parallel, omp_get_thread_num, &
  !$                     omp_get_num_threads
  implicit none
  private
  public :: sorted_t, gather_sorted, scatter_rates, copy_to_images, thread_lists, one_thread, &
            team_work_t, in_team, in_open_team, set_open_team, SKIN_PER_H
  public :: N_RATE, R_AX, R_AZ, R_AR, R_XU, R_XW

  !> Rows of sorted_t%rate, a slot's accumulated rates: acceleration x, z, density rate and
  !> the XSPH sums u, w
  integer, parameter :: R_AX = 1, R_AZ = 2, R_AR = 3, R_XU = 4, R_XW = 5, N_RATE = 5

  !> Whether this thread runs in a team that a caller has opened for several sets of loops
  !> (predictor_corrector.f90: one parallel region per step). Every thread of that team then
  !> calls in_team, gather_sorted, pair_sweep and scatter_rates together, and their loops
  !> are the team's orphaned worksharing loops (no region of their own). Per thread, so that
  !> the thread that runs a `single` section can clear it there (gather_sorted).
  logical, save :: open_team = .false.
  !$omp threadprivate(open_team)

  !> Skin of the neighbour list in units of h (cutoff 2h + skin). Measured (1 thread,
  !> alternated, after the rates lost three divisions per pair): 0.2 h against 0.3 h Case1
  !> +3% (bench) and +2% (the whole run to 3 s), ObstW +3%; 0.1 and 0.15 h as 0.2, 0.4 h 3%
  !> slower. A smaller skin lists fewer pairs beyond 2h, a larger one builds less often.
  real(rp), parameter :: SKIN_PER_H = 0.2_rp

  type :: sorted_t
    integer :: n = 0
    type(cell_grid_t) :: grid
    real(rp), allocatable :: x(:), z(:), u(:), w(:), rho(:), p(:), c(:), m(:), pr(:)
    logical, allocatable :: fluid(:)
    integer :: n_real = 0                !< slots of real particles (n - n_real are images)
    integer, allocatable :: src(:)       !< particle (state index) each slot stands for
    integer, allocatable :: src_slot(:)  !< the slot of that particle (k itself for a real slot)
    real(rp), allocatable :: usign(:)    !< -1 for a mirror image across the axis, else 1
    real(rp), allocatable :: zshift(:)   !< z shift of a periodic image (+-lz), else 0
    !> accumulated rates (sorted order), rate(R_*, k): one slot's sums side by side, so that
    !> a pair's additions to its neighbour b touch one place in memory
    real(rp), allocatable :: rate(:, :)
    !> The rings pair's truncation vector (loops/axisymmetric_loops.f90, ring_rates), set with
    !> the rates and read by the CSF force of the same evaluation
    real(rp), allocatable :: axi_dx(:), axi_dz(:)
    ! per-particle inputs of the rates loop (loops/rates.f90): tensile R and repulsive-wall
    ! geometry, kept here so that an evaluation allocates (and page-faults) nothing
    real(rp), allocatable :: tr(:), wnx(:), wnz(:), wdb(:), wdf(:)
    ! one pair list per thread, and the kept pairs of each row (traversal.f90)
    type(pair_list_t), allocatable :: lists(:), cache(:)
    ! the neighbour list: pairs of each row task (rows(0:grid%ncz-1)), build positions
    ! (particle order), and what the build saw
    type(row_list_t), allocatable :: rows(:)
    !> The row tasks in the order a sweep hands them out: the even rows, then the odd ones
    !> (an odd row waits for the even rows next to it), each by decreasing number of listed
    !> pairs, so that the sweep ends on small tasks and the threads finish it together
    !> (row_phases)
    integer, allocatable :: row_order(:)
    !> Sweeps by a team (traversal.f90, sweep_thread): the row tasks each row has finished
    !> since the last build (rows(0:ncz-1), all equal between sweeps), the number of tasks
    !> handed out and of threads done handing out in the sweep under way
    integer, allocatable :: row_done(:)
    integer :: next_task = 0, threads_out = 0
    real(rp), allocatable :: xb(:), zb(:)
    logical :: built = .false.
    logical :: imaged = .false.            !< the list was built with image particles
    integer :: n_all = -1, n_active = -1
    integer :: n_builds = 0                !< builds so far (diagnostics)
    ! an open team's list check and build (gather_sorted): each thread's share of the check,
    ! and a build whose row lists the team makes (build leaves them to it with defer_rows)
    integer, allocatable :: part_na(:)
    real(rp), allocatable :: part_d2(:)
    logical, allocatable :: part_same(:)
    logical :: defer_rows = .false., rows_pending = .false.
    logical, allocatable :: real_slot(:)   !< slots of particles, not images, at the build
    real(rp) :: cut2 = 0.0_rp               !< (2h + skin)^2 of the build
    real(rp) :: skin_per_h = SKIN_PER_H    !< 0: list exactly the pairs closer than 2h
    logical :: all_pairs = .false.         !< list boundary-boundary pairs too
  end type sorted_t

  !> Particle loops for in_team: run(which) holds orphaned worksharing loops (!$omp do) and
  !> is called by every thread of a parallel region, or by this thread alone.
  type, abstract :: team_work_t
  contains
    procedure(team_run_i), deferred :: run
  end type team_work_t

  abstract interface
    subroutine team_run_i(self, which)
      import :: team_work_t
      class(team_work_t), intent(inout) :: self
      integer, intent(in) :: which
    end subroutine team_run_i
  end interface

  !> The particle loops of this module: which = GATHER, SCATTER or MOVES.
  integer, parameter :: GATHER = 1, SCATTER = 2, MOVES = 3
  type, extends(team_work_t) :: sorted_work_t
    type(sorted_t), pointer :: s => null()
    type(state_t), pointer :: st => null()
    logical :: images = .false.
    real(rp) :: xsph_eps = 0.0_rp, d2max = 0.0_rp
    integer :: nact = 0
  contains
    procedure :: run => sorted_run
  end type sorted_work_t

contains

  !> Gathers the fields of the active particles in sorted order, building the sorted order
  !> and the neighbour list first when they are missing or no longer cover the state; with
  !> prm (axisymmetric or periodic in z) also their image particles and the planar masses.
  subroutine gather_sorted(st, h, s, prm)
    type(state_t), intent(inout), target :: st
    real(rp), intent(in) :: h
    type(sorted_t), intent(inout), target :: s
    type(sph_params_t), intent(in), optional :: prm
    integer :: n
    logical :: images, axi
    type(sorted_work_t) :: work

    if (open_team) then
      ! every thread of the step's team (no images there: predictor_corrector.f90): the team
      ! checks whether the list still serves; if not, one thread decides and sorts as
      ! update_list does, and the team makes the row lists
      if (team_list_stale(st, h, s)) then
        !$omp single
        open_team = .false.   ! loops of a build in a (nested, one-thread) region of their own
        s%defer_rows = .true.
        call update_list(st, h, s)
        s%defer_rows = .false.
        open_team = .true.
        !$omp end single
        if (s%rows_pending) then
          call build_verlet_rows(s%grid, s%x(1:s%n), s%z(1:s%n), s%fluid(1:s%n), &
                                 s%real_slot(1:s%n), s%cut2, &
                                 s%all_pairs, s%lists, s%rows, team=.true.)
          !$omp single
          call row_phases(s)
          s%rows_pending = .false.
          !$omp end single
        end if
      end if
      work%st => st
      work%s => s
      call in_team(work, GATHER)
      return
    end if
    images = .false.
    axi = .false.
    if (present(prm)) then
      axi = prm%geometry%kind == GEOM_AXISYMMETRIC
      images = axi .or. prm%geometry%periodic_z /= 0
    end if
    if (images) then
      call update_list(st, h, s, prm)
    else
      call update_list(st, h, s)
    end if
    n = s%n
    work%st => st
    work%s => s
    work%images = images
    call in_team(work, GATHER)
    if (axi) s%m(1:n) = planar_mass(s%m(1:n), s%x(1:n), h)
  end subroutine gather_sorted

  !> Whether update_list might build (called by every thread of an open team, the same
  !> answer in all): .false. exactly when update_list would keep the list (no images): built
  !> for these particles, the caller's build positions ours, the same active particles,
  !> none moved more than skin/2. Each thread checks a static share of the particles; the
  !> shares are combined after a barrier, by every thread in the same order. Every thread
  !> reads what a build changes (s%built, s%xb, s%n_active, ...) before that barrier, and
  !> after it only the shares: the thread that then builds (gather_sorted) cannot change
  !> what another is still reading.
  logical function team_list_stale(st, h, s) result(stale)
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: h
    type(sorted_t), intent(inout) :: s
    integer :: j, me, nt, na, n_active
    real(rp) :: d2, d2_max
    logical :: same, listed
    me = 1
    nt = 1
    !$ me = omp_get_thread_num() + 1
    !$ nt = omp_get_num_threads()
    same = s%built .and. s%n_all == st%n .and. .not. s%imaged
    n_active = s%n_active
    d2_max = (0.5_rp * s%skin_per_h * h)**2
    na = 0
    d2 = 0.0_rp
    if (same) then   ! the same in every thread
      listed = associated(st%list_x) .and. associated(st%list_z)
      !$omp do schedule(static)
      do j = 1, st%n
        if (listed) same = same .and. s%xb(j) == st%list_x(j) .and. s%zb(j) == st%list_z(j)
        call add_move(st, s, j, na, d2)
      end do
      !$omp end do nowait
    end if
    s%part_na(me) = na
    s%part_d2(me) = d2
    s%part_same(me) = same
    !$omp barrier
    stale = .not. (all(s%part_same(1:nt)) .and. sum(s%part_na(1:nt)) == n_active .and. &
                   maxval(s%part_d2(1:nt)) <= d2_max)
  end function team_list_stale

  !> The sorted order and the neighbour list (with prm: of the particles and their images),
  !> built again when the caller's build positions differ from ours or a particle has moved
  !> more than skin/2 since the build (or the active set changed).
  subroutine update_list(st, h, s, prm)
    type(state_t), intent(inout), target :: st
    real(rp), intent(in) :: h
    type(sorted_t), intent(inout), target :: s
    type(sph_params_t), intent(in), optional :: prm   !< a run with image particles
    real(rp) :: skin, d2max
    integer :: nact
    logical :: valid, alone
    type(sorted_work_t) :: work
    skin = s%skin_per_h * h
    valid = s%built .and. s%n_all == st%n .and. (s%imaged .eqv. present(prm))
    if (associated(st%list_x) .and. associated(st%list_z)) then
      ! the caller's build positions are the reference; ours may be of another run
      if (valid) valid = all(s%xb(1:st%n) == st%list_x) .and. all(s%zb(1:st%n) == st%list_z)
      if (.not. valid .and. listed_positions(st)) then
        call build_from(st%list_x, st%list_z)
        valid = .true.
      end if
    end if
    if (valid) then
      work%st => st
      work%s => s
      alone = .false.
      !$ alone = omp_in_parallel()
      if (alone) then   ! in an open team's single section (gather_sorted)
        call count_moves(st, s, work%nact, work%d2max, .true.)
      else
        call in_team(work, MOVES)
      end if
      nact = work%nact
      d2max = work%d2max
      valid = nact == s%n_active .and. d2max <= (0.5_rp * skin)**2
    end if
    if (.not. valid) then
      call build_from(st%x, st%z)
      if (associated(st%list_x) .and. associated(st%list_z)) then
        st%list_x = st%x
        st%list_z = st%z
      end if
    end if
  contains
    !> The list of the particles at xl, zl, with their images there, and the slots' sources
    !> (which change only here).
    subroutine build_from(xl, zl)
      real(rp), intent(in) :: xl(:), zl(:)
      if (present(prm)) then
        call build_imaged(st, xl, zl, h, skin, prm, s)
      else
        call build(xl, zl, st%active, st%kind == KIND_FLUID, h, skin, s)
        s%imaged = .false.
      end if
      call slot_sources(st, s, present(prm))
    end subroutine build_from
  end subroutine update_list

  !> The list of the st%n particles at their build positions xl, zl and of their images
  !> there (image_particles, within 2h + skin of the axis and the z ends), and each slot's
  !> source particle, x and u sign and z shift, which place the images at every gather
  !> (gather_all).
  subroutine build_imaged(st, xl, zl, h, skin, prm, s)
    type(state_t), intent(in) :: st
    real(rp), intent(in) :: xl(:), zl(:), h, skin
    type(sph_params_t), intent(in) :: prm
    type(sorted_t), intent(inout) :: s
    real(rp), allocatable :: xe(:), ze(:), sg(:), dz(:)
    integer(ip), allocatable :: ae(:)
    integer, allocatable :: isrc(:)
    logical, allocatable :: fe(:)
    integer :: i, k, n
    n = st%n
    call image_particles(xl(1:n), zl(1:n), st%active(1:n), 2.0_rp * h + skin, prm, &
                         prm%geometry%kind == GEOM_AXISYMMETRIC, xe, ze, ae, isrc, sg, dz)
    allocate(fe(size(xe)))
    fe(1:n) = st%kind(1:n) == KIND_FLUID
    do i = n + 1, size(xe)
      fe(i) = st%kind(isrc(i - n)) == KIND_FLUID
    end do
    call build(xe, ze, ae, fe, h, skin, s, n_real=n)
    s%imaged = .true.
    do k = 1, s%n
      i = s%grid%order(k)
      if (i <= n) then
        s%src(k) = i
        s%usign(k) = 1.0_rp
        s%zshift(k) = 0.0_rp
      else
        s%src(k) = isrc(i - n)
        s%usign(k) = sg(i - n)
        s%zshift(k) = dz(i - n)
      end if
    end do
  end subroutine build_imaged

  !> s%n_real, and the slot of each slot's source particle (src_slot; needs s%src with
  !> images, from build_imaged). Both change only at a build (the active set is that of the
  !> build until the next one).
  subroutine slot_sources(st, s, images)
    type(state_t), intent(in) :: st
    type(sorted_t), intent(inout) :: s
    logical, intent(in) :: images
    integer :: k
    integer, allocatable :: isrc_slot(:)
    s%n_real = count(st%active(1:st%n) /= 0)
    if (images) then
      ! the slot of each image's source: multi-pass loops (CSF) copy the source's fields to
      ! its images between passes, since an image's own sums lack the neighbours beyond the
      ! image band (copy_to_images)
      allocate(isrc_slot(st%n))
      do k = 1, s%n
        if (s%grid%order(k) <= st%n) isrc_slot(s%grid%order(k)) = k
      end do
      do k = 1, s%n
        s%src_slot(k) = isrc_slot(s%src(k))
      end do
    else
      do k = 1, s%n
        s%src_slot(k) = k
      end do
    end if
  end subroutine slot_sources

  !> Runs work%run(which) in a parallel region, or directly when one thread is in use
  !> (one_thread: no region, no barrier) or when every thread of an open team calls it
  !> (set_open_team).
  subroutine in_team(work, which)
    class(team_work_t), intent(inout) :: work
    integer, intent(in) :: which
    if (one_thread() .or. open_team) then
      call work%run(which)
    else
      !$omp parallel
      call work%run(which)
      !$omp end parallel
    end if
  end subroutine in_team

  subroutine sorted_run(self, which)
    class(sorted_work_t), intent(inout) :: self
    integer, intent(in) :: which
    select case (which)
    case (GATHER)
      call gather_all(self%st, self%s, self%images)
    case (SCATTER)
      call scatter_all(self%s, self%st, self%xsph_eps)
    case default
      call count_moves(self%st, self%s, self%nact, self%d2max)
    end select
  end subroutine sorted_run

  !> Active particles (na) and their largest squared move since the build (d2): zero in,
  !> reduced over the threads (a worksharing loop), or by this thread alone.
  subroutine count_moves(st, s, na, d2, alone)
    type(state_t), intent(in) :: st
    type(sorted_t), intent(in) :: s
    integer, intent(inout) :: na
    real(rp), intent(inout) :: d2
    logical, intent(in), optional :: alone
    integer :: j
    if (present(alone)) then
      do j = 1, st%n
        call add_move(st, s, j, na, d2)
      end do
      return
    end if
    !$omp do schedule(static) reduction(+:na) reduction(max:d2)
    do j = 1, st%n
      call add_move(st, s, j, na, d2)
    end do
    !$omp end do
  end subroutine count_moves

  pure subroutine add_move(st, s, j, na, d2)
    type(state_t), intent(in) :: st
    type(sorted_t), intent(in) :: s
    integer, intent(in) :: j
    integer, intent(inout) :: na
    real(rp), intent(inout) :: d2
    if (st%active(j) == 0) return
    na = na + 1
    d2 = max(d2, (st%x(j) - s%xb(j))**2 + (st%z(j) - s%zb(j))**2)
  end subroutine add_move

  !> The fields of the source particles s%src(1:s%n) into the slots of s, an image's x and u
  !> times its sign and its z shifted (build_imaged), and zero sums. One field at a time:
  !> each loop's scattered reads then fall in one source array, small enough to stay in the
  !> second-level cache, instead of ten at once. Same values as slot by slot.
  subroutine gather_all(st, s, images)
    type(state_t), intent(in) :: st
    type(sorted_t), intent(inout) :: s
    logical, intent(in) :: images
    integer :: k, n
    n = s%n
    if (.not. images) then   ! the slot's particle (same static schedule as the loops below)
      !$omp do schedule(static)
      do k = 1, n
        s%src(k) = s%grid%order(k)
        s%usign(k) = 1.0_rp
      end do
      !$omp end do nowait
    end if
    call permute(st%x, s%x)
    call permute(st%z, s%z)
    call permute(st%u, s%u)
    call permute(st%w, s%w)
    call permute(st%rho, s%rho)
    call permute(st%p, s%p)
    call permute(st%c, s%c)
    call permute(st%m, s%m)
    ! the same static schedule as the loops above: slot k is this thread's in all of them
    !$omp do schedule(static)
    do k = 1, n
      if (images) then
        s%x(k) = s%usign(k) * s%x(k)
        s%z(k) = s%z(k) + s%zshift(k)
        s%u(k) = s%usign(k) * s%u(k)
      end if
      s%pr(k) = s%p(k) / (s%rho(k) * s%rho(k))
      s%fluid(k) = st%kind(s%src(k)) == KIND_FLUID
      call clear_sums(s, k)
    end do
    !$omp end do
  contains
    subroutine permute(src, dst)
      real(rp), intent(in) :: src(*)
      real(rp), intent(inout) :: dst(*)
      integer :: j
      !$omp do schedule(static)
      do j = 1, n
        dst(j) = src(s%src(j))
      end do
      !$omp end do nowait
    end subroutine permute
  end subroutine gather_all

  !> Zero rate sums of slot k.
  pure subroutine clear_sums(s, k)
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: k
    s%rate(1:N_RATE, k) = 0.0_rp
  end subroutine clear_sums

  !> The accumulated rates of the sorted slots back to particle order: st%ax, az, ar and
  !> xsph_eps times the XSPH sums; inactive particles get zero rates. The sorted slots are
  !> exactly the active particles, so the two loops write disjoint entries and need no
  !> barrier between them (nowait). Image slots are not scattered: their sums are discarded.
  subroutine scatter_rates(s, st, xsph_eps)
    type(sorted_t), intent(in), target :: s
    type(state_t), intent(inout), target :: st
    real(rp), intent(in) :: xsph_eps
    type(sorted_work_t) :: work
    work%s => s
    work%st => st
    work%xsph_eps = xsph_eps
    call in_team(work, SCATTER)
  end subroutine scatter_rates

  !> The loops of scatter_rates (in_team's SCATTER): every thread its static share of the
  !> slots, a slot's five sums (side by side in rate) back to particle order in one pass;
  !> inactive particles get zeros. Image slots (grid%order(k) > st%n) are skipped.
  subroutine scatter_all(s, st, xsph_eps)
    type(sorted_t), intent(in) :: s
    type(state_t), intent(inout) :: st
    real(rp), intent(in) :: xsph_eps
    integer :: i
    call scatter_slots(s%n, s%grid%order, st%n, xsph_eps, s%rate, st%ax, st%az, st%ar, &
                       st%xsph_u, st%xsph_w)
    !$omp do schedule(static)
    do i = 1, st%n
      if (st%active(i) /= 0) cycle
      st%ax(i) = 0.0_rp
      st%az(i) = 0.0_rp
      st%ar(i) = 0.0_rp
      st%xsph_u(i) = 0.0_rp
      st%xsph_w(i) = 0.0_rp
    end do
    !$omp end do
  end subroutine scatter_all

  !> scatter_all's pass over the slots k (plain arrays, so that the loop keeps their
  !> addresses in registers): the sums of a real slot to particle i = order(k) <= n_state,
  !> XSPH times xsph_eps. Called by every thread of a parallel region; no wait at the end.
  subroutine scatter_slots(n, order, n_state, xsph_eps, r, ax, az, ar, xu, xw)
    integer, intent(in) :: n, order(*), n_state
    real(rp), intent(in) :: xsph_eps, r(N_RATE, *)
    real(rp), intent(inout) :: ax(*), az(*), ar(*), xu(*), xw(*)
    integer :: k, i
    !$omp do schedule(static)
    do k = 1, n
      i = order(k)
      if (i > n_state) cycle
      ax(i) = r(R_AX, k)
      az(i) = r(R_AZ, k)
      ar(i) = r(R_AR, k)
      xu(i) = xsph_eps * r(R_XU, k)
      xw(i) = xsph_eps * r(R_XW, k)
    end do
    !$omp end do nowait
  end subroutine scatter_slots

  !> Whether the caller's build positions are usable: finite for every active particle.
  logical function listed_positions(st)
    type(state_t), intent(in) :: st
    integer :: i
    listed_positions = .true.
    do i = 1, st%n
      if (st%active(i) == 0) cycle
      if (ieee_is_finite(st%list_x(i)) .and. ieee_is_finite(st%list_z(i))) cycle
      listed_positions = .false.
      return
    end do
  end function listed_positions

  !> Sorts the active entries of xl, zl (the particles, then any images) by cell of side
  !> 2h + skin and lists their pairs closer than 2h + skin there (with at least one fluid
  !> entry, fl, and at least one of the first n_real entries, the particles; default all);
  !> keeps those n_real entries of xl, zl as the build positions.
  subroutine build(xl, zl, act, fl, h, skin, s, n_real)
    real(rp), intent(in) :: xl(:), zl(:), h, skin
    integer(ip), intent(in) :: act(:)
    logical, intent(in) :: fl(:)
    type(sorted_t), intent(inout) :: s
    integer, intent(in), optional :: n_real
    integer :: k, i, n, n_all, nr
    real(rp) :: cut

    cut = 2.0_rp * h + skin
    n_all = size(xl)
    nr = n_all
    if (present(n_real)) nr = n_real
    call build_cell_list(xl, zl, act, cut, s%grid)
    n = s%grid%nsorted
    s%n = n
    call ensure(s, n, nr)
    s%xb(1:nr) = xl(1:nr)
    s%zb(1:nr) = zl(1:nr)
    s%n_all = nr
    s%n_active = count(act(1:nr) /= 0)   ! n without images
    s%built = .true.
    s%n_builds = s%n_builds + 1
    call thread_lists(s)
    if (allocated(s%rows)) then
      if (size(s%rows) < s%grid%ncz) deallocate(s%rows)
    end if
    if (.not. allocated(s%rows)) allocate(s%rows(0:s%grid%ncz - 1))
    ! the build positions in sorted order (s%x, s%z are gathered again afterwards)
    do k = 1, n
      i = s%grid%order(k)
      s%x(k) = xl(i)
      s%z(k) = zl(i)
      s%fluid(k) = fl(i)
      s%real_slot(k) = i <= nr
    end do
    s%cut2 = cut * cut
    if (s%defer_rows) then   ! an open team makes the row lists (gather_sorted)
      s%rows_pending = .true.
      return
    end if
    call build_verlet_rows(s%grid, s%x(1:n), s%z(1:n), s%fluid(1:n), s%real_slot(1:n), &
                           s%cut2, s%all_pairs, s%lists, s%rows)
    call row_phases(s)
  end subroutine build

  !> s%row_order: the even rows by decreasing listed pairs, then the odd rows likewise (ties
  !> by row), and the sweeps' counters (row_done, all 0). Which thread runs a row and when
  !> changes no sum: rows of one parity write disjoint particles, an odd row waits for its
  !> even neighbours, and each row's pairs are visited in its own order (traversal.f90).
  subroutine row_phases(s)
    type(sorted_t), intent(inout) :: s
    integer :: ncz, i, j, r, k
    ncz = s%grid%ncz
    if (allocated(s%row_order)) then
      if (size(s%row_order) < ncz) deallocate(s%row_order)
    end if
    if (.not. allocated(s%row_order)) allocate(s%row_order(ncz))
    k = 0
    do r = 0, ncz - 1, 2
      k = k + 1
      s%row_order(k) = r
    end do
    do r = 1, ncz - 1, 2
      k = k + 1
      s%row_order(k) = r
    end do
    call by_pairs(1, (ncz + 1) / 2)
    call by_pairs((ncz + 1) / 2 + 1, ncz)
    if (allocated(s%row_done)) then
      if (size(s%row_done) < ncz) deallocate(s%row_done)
    end if
    if (.not. allocated(s%row_done)) allocate(s%row_done(0:ncz - 1))
    s%row_done = 0
    s%next_task = 0
    s%threads_out = 0
  contains
    !> Insertion sort of row_order(i0:i1) by decreasing listed pairs (stable).
    subroutine by_pairs(i0, i1)
      integer, intent(in) :: i0, i1
      do i = i0 + 1, i1
        r = s%row_order(i)
        j = i - 1
        do while (j >= i0)
          if (s%rows(s%row_order(j))%n >= s%rows(r)%n) exit
          s%row_order(j + 1) = s%row_order(j)
          j = j - 1
        end do
        s%row_order(j + 1) = r
      end do
    end subroutine by_pairs
  end subroutine row_phases

  !> Whether the next parallel regions would have one thread. Then the loops run without a
  !> region (their orphaned worksharing constructs serially): with libgomp every barrier, and
  !> so every region, costs a futex system call even for a team of one, and a small case's
  !> step has dozens of them. Not in a parallel region: a thread alone in a team's `single`
  !> section must open a (nested, one-thread) region for orphaned loops.
  logical function one_thread()
    one_thread = .true.
    !$ one_thread = omp_get_max_threads() == 1 .and. .not. omp_in_parallel()
  end function one_thread

  !> Whether this thread is one of an open team (set_open_team) whose threads all call the
  !> particle loops together.
  logical function in_open_team()
    in_open_team = open_team
  end function in_open_team

  !> Every thread of a parallel region calls this with .true. at its start (the loops called
  !> afterwards run as the region's orphaned worksharing loops) and with .false. at its end.
  subroutine set_open_team(on)
    logical, intent(in) :: on
    open_team = on
  end subroutine set_open_team

  !> One pair list per thread (at least omp_get_max_threads()), kept in the work space from
  !> sweep to sweep.
  subroutine thread_lists(s)
    type(sorted_t), intent(inout) :: s
    integer :: nt
    nt = 1
    !$ nt = omp_get_max_threads()
    if (allocated(s%lists)) then
      if (size(s%lists) < nt) deallocate(s%lists)
    end if
    if (.not. allocated(s%lists)) allocate(s%lists(nt))
    if (allocated(s%part_na)) then
      if (size(s%part_na) < nt) deallocate(s%part_na, s%part_d2, s%part_same)
    end if
    if (.not. allocated(s%part_na)) allocate(s%part_na(nt), s%part_d2(nt), s%part_same(nt))
  end subroutine thread_lists

  !> The positions xl, zl of the particles (active act) followed by their images within
  !> reach of the axis and of the z ends (xe, ze, active ae), each image's source particle
  !> isrc, x and u sign sg (-1 across the axis) and z shift dz (0 or -+lz). Serial and in
  !> particle order: the same images in the same order whatever the thread count.
  subroutine image_particles(xl, zl, act, reach, prm, axi, xe, ze, ae, isrc, sg, dz)
    real(rp), intent(in) :: xl(:), zl(:), reach
    integer(ip), intent(in) :: act(:)
    type(sph_params_t), intent(in) :: prm
    logical, intent(in) :: axi
    real(rp), allocatable, intent(out) :: xe(:), ze(:), sg(:), dz(:)
    integer(ip), allocatable, intent(out) :: ae(:)
    integer, allocatable, intent(out) :: isrc(:)
    integer :: n, i, m, m1, j, cap
    real(rp) :: lz, zlo, zhi, sgn
    logical :: per
    n = size(xl)
    per = prm%geometry%periodic_z /= 0
    lz = prm%domain%zmax - prm%domain%zmin
    zlo = prm%domain%zmin + reach
    zhi = prm%domain%zmax - reach
    ! at most one axis image per particle, and two periodic images per particle or axis image
    cap = n
    if (axi) cap = cap + n
    if (per) cap = cap + 2 * cap
    allocate(xe(cap), ze(cap), ae(cap), isrc(cap - n), sg(cap - n), dz(cap - n))
    xe(1:n) = xl
    ze(1:n) = zl
    ae(1:n) = act
    m = n
    if (axi) then
      do i = 1, n
        if (act(i) == 0 .or. abs(xl(i)) >= reach) cycle
        call add(i, -xl(i), zl(i), -1.0_rp, 0.0_rp)
      end do
    end if
    if (per) then
      m1 = m
      do j = 1, m1   ! the particles and their axis images
        if (ae(j) == 0) cycle
        i = j
        sgn = 1.0_rp
        if (j > n) then
          i = isrc(j - n)
          sgn = sg(j - n)
        end if
        if (ze(j) < zlo) call add(i, xe(j), ze(j) + lz, sgn, lz)
        if (ze(j) > zhi) call add(i, xe(j), ze(j) - lz, sgn, -lz)
      end do
    end if
    ! shrink to the slots used (build_cell_list sizes its work by size(x))
    xe = xe(1:m)
    ze = ze(1:m)
    ae = ae(1:m)
  contains
    subroutine add(src, x, z, sgn, shift)
      integer, intent(in) :: src
      real(rp), intent(in) :: x, z, sgn, shift
      m = m + 1
      xe(m) = x
      ze(m) = z
      ae(m) = 1
      isrc(m - n) = src
      sg(m - n) = sgn
      dz(m - n) = shift
    end subroutine add
  end subroutine image_particles

  !> Sets every image slot of f to its source slot's value times sgn (1, or s%usign for the
  !> radial component of a vector); real slots are left alone.
  subroutine copy_to_images(s, f, radial)
    type(sorted_t), intent(in) :: s
    real(rp), intent(inout) :: f(:)
    logical, intent(in) :: radial
    integer :: k
    do k = 1, s%n
      if (s%src_slot(k) == k) cycle
      f(k) = f(s%src_slot(k))
      if (radial) f(k) = s%usign(k) * f(k)
    end do
  end subroutine copy_to_images

  subroutine ensure(s, n, n_all)
    type(sorted_t), intent(inout) :: s
    integer, intent(in) :: n, n_all
    if (allocated(s%xb)) then
      if (size(s%xb) < n_all) deallocate(s%xb, s%zb)
    end if
    if (.not. allocated(s%xb)) allocate(s%xb(n_all), s%zb(n_all))
    if (allocated(s%x)) then
      if (size(s%x) >= n) return
      deallocate(s%x, s%z, s%u, s%w, s%rho, s%p, s%c, s%m, s%pr, s%fluid, s%real_slot, &
                 s%rate, s%src, s%usign, s%zshift, s%src_slot, &
                 s%tr, s%wnx, s%wnz, s%wdb, s%wdf)
    end if
    allocate(s%x(n), s%z(n), s%u(n), s%w(n), s%rho(n), s%p(n), s%c(n), s%m(n), s%pr(n), &
             s%fluid(n), s%real_slot(n), s%rate(N_RATE, n), s%src(n), s%usign(n), &
             s%zshift(n), s%src_slot(n), s%tr(n), s%wnx(n), s%wnz(n), s%wdb(n), s%wdf(n))
  end subroutine ensure

end module sorted_state
