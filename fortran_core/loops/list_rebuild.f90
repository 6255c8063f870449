!> When to build the neighbour list again, and the build. gather_sorted, which every pair
!> loop calls first, is the one place that decides the neighbour list
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
module list_rebuild
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use sphjet_kinds, only: rp, ip, KIND_FLUID, GEOM_AXISYMMETRIC
  use sphjet_types, only: state_t, sph_params_t
  use axisymmetric, only: planar_mass
  use cell_list, only: build_cell_list
  use verlet_list, only: build_verlet_rows
  use sorted_state, only: sorted_t, gather_fields, thread_lists, ensure
  use particle_images, only: image_particles
  use omp_team, only: team_work_t, in_team, in_open_team, set_open_team
  !$ use omp_lib, only: omp_in_parallel, omp_get_thread_num, omp_get_num_threads
  implicit none
  private
  public :: gather_sorted

  !> The list check's particle loop for in_team (which = MOVES): the active particles and
  !> their largest squared move since the build (count_moves).
  integer, parameter :: MOVES = 1
  type, extends(team_work_t) :: moves_work_t
    type(sorted_t), pointer :: s => null()
    type(state_t), pointer :: st => null()
    real(rp) :: d2max = 0.0_rp
    integer :: nact = 0
  contains
    procedure :: run => moves_run
  end type moves_work_t

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

    if (in_open_team()) then
      ! every thread of the step's team (no images there: predictor_corrector.f90): the team
      ! checks whether the list still serves; if not, one thread decides and sorts as
      ! update_list does, and the team makes the row lists
      if (team_list_stale(st, h, s)) then
        !$omp single
        call set_open_team(.false.)   ! loops of a build in a (nested, one-thread) region of their own
        s%defer_rows = .true.
        call update_list(st, h, s)
        s%defer_rows = .false.
        call set_open_team(.true.)
        !$omp end single
        if (s%rows_pending) then
          call build_verlet_rows(s%grid, s%x(1:s%n), s%z(1:s%n), s%fluid(1:s%n), &
                                 s%real_slot(1:s%n), s%cut2, &
                                 s%all_pairs, s%lists, s%rows, team=.true.)
          !$omp single
          call row_counters(s)
          s%rows_pending = .false.
          !$omp end single
        end if
      end if
      call gather_fields(st, s, .false.)
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
    call gather_fields(st, s, images)
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
    type(moves_work_t) :: work
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

  subroutine moves_run(self, which)
    class(moves_work_t), intent(inout) :: self
    integer, intent(in) :: which
    if (which == MOVES) call count_moves(self%st, self%s, self%nact, self%d2max)
  end subroutine moves_run

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
    call row_counters(s)
  end subroutine build

  !> The sweeps' row counters (row_done, all 0) and the listed pairs before each row
  !> (row_cum), by which a team's sweep splits the rows among its threads (traversal.f90).
  subroutine row_counters(s)
    type(sorted_t), intent(inout) :: s
    integer :: ncz, r
    ncz = s%grid%ncz
    if (allocated(s%row_done)) then
      if (size(s%row_done) < ncz) deallocate(s%row_done)
    end if
    if (.not. allocated(s%row_done)) allocate(s%row_done(0:ncz - 1))
    s%row_done = 0
    s%sweeps = 0
    if (allocated(s%row_cum)) then
      if (size(s%row_cum) < ncz + 1) deallocate(s%row_cum)
    end if
    if (.not. allocated(s%row_cum)) allocate(s%row_cum(0:ncz))
    s%row_cum(0) = 0
    do r = 0, ncz - 1
      s%row_cum(r + 1) = s%row_cum(r) + s%rows(r)%n
    end do
  end subroutine row_counters

end module list_rebuild
