!> The active particles gathered in cell order (contiguous per cell), the layout every pair
!> traversal works on; rates are accumulated here and scattered back afterwards.
!> The list (its build and when to build it again: list_rebuild.f90) and the image particles
!> (particle_images.f90) live in the same work space, sorted_t.
module sorted_state
  use sphjet_kinds, only: rp, KIND_FLUID
  use sphjet_types, only: state_t
  use cell_list, only: cell_grid_t
  use pair_list, only: pair_list_t
  use verlet_list, only: row_list_t
  use omp_team, only: team_work_t, in_team
  !$ use omp_lib, only: omp_get_max_threads
  implicit none
  private
  public :: sorted_t, gather_fields, scatter_rates, thread_lists, ensure, SKIN_PER_H
  public :: N_RATE, R_AX, R_AZ, R_AR, R_XU, R_XW

  !> Rows of sorted_t%rate, a slot's accumulated rates: acceleration x, z, density rate and
  !> the XSPH sums u, w
  integer, parameter :: R_AX = 1, R_AZ = 2, R_AR = 3, R_XU = 4, R_XW = 5, N_RATE = 5

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
    !> The shifting velocity of each slot (numerics.shifting; surface_tension_loops.f90),
    !> shift(1:2, k), set with the rates and added to the XSPH velocity by the scatter;
    !> allocated by shifting's first use
    real(rp), allocatable :: shift(:, :)
    ! per-particle inputs of the rates loop (loops/rates.f90): tensile R and repulsive-wall
    ! geometry, kept here so that an evaluation allocates (and page-faults) nothing
    real(rp), allocatable :: tr(:), wnx(:), wnz(:), wdb(:), wdf(:)
    !> The velocity gradient of each slot for the reconstructed artificial viscosity
    !> (velocity_gradient_loops.f90): gv(G_*, k), allocated by its first use
    real(rp), allocatable :: gv(:, :)
    ! one pair list per thread, and the kept pairs of each row (traversal.f90)
    type(pair_list_t), allocatable :: lists(:), cache(:)
    ! the neighbour list: pairs of each row task (rows(0:grid%ncz-1)), build positions
    ! (particle order), and what the build saw
    type(row_list_t), allocatable :: rows(:)
    !> Sweeps by a team (traversal.f90, sweep_thread): the row tasks each row has finished
    !> since the last build (rows(0:ncz-1), all equal to sweeps between sweeps); the rows of
    !> each parity each thread's block has handed out from its bottom and its top in the
    !> sweep under way (claims(0:1, thread): bottom + 2**32 top); the threads done with it
    integer, allocatable :: row_done(:)
    integer :: sweeps = 0, threads_out = 0
    integer(8), allocatable :: claims(:, :)
    !> Listed pairs of the rows before each row (row_cum(0:ncz); row_cum(ncz) all of them):
    !> where a team's sweep splits the rows among its threads (traversal.f90, block_start)
    integer, allocatable :: row_cum(:)
    real(rp), allocatable :: xb(:), zb(:)
    logical :: built = .false.
    logical :: imaged = .false.            !< the list was built with image particles
    integer :: n_all = -1, n_active = -1
    integer :: n_builds = 0                !< builds so far (diagnostics)
    ! an open team's list check and build (gather_sorted, list_rebuild.f90): each thread's
    ! share of the check, and a build whose row lists the team makes (build leaves them to it
    ! with defer_rows)
    integer, allocatable :: part_na(:)
    real(rp), allocatable :: part_d2(:)
    logical, allocatable :: part_same(:)
    logical :: defer_rows = .false., rows_pending = .false.
    logical, allocatable :: real_slot(:)   !< slots of particles, not images, at the build
    real(rp) :: cut2 = 0.0_rp               !< (2h + skin)^2 of the build
    real(rp) :: skin_per_h = SKIN_PER_H    !< 0: list exactly the pairs closer than 2h
    logical :: all_pairs = .false.         !< list boundary-boundary pairs too
  end type sorted_t

  !> The particle loops of this module: which = GATHER or SCATTER.
  integer, parameter :: GATHER = 1, SCATTER = 2
  type, extends(team_work_t) :: sorted_work_t
    type(sorted_t), pointer :: s => null()
    type(state_t), pointer :: st => null()
    logical :: images = .false.
    real(rp) :: xsph_eps = 0.0_rp
    logical :: shifted = .false.
  contains
    procedure :: run => sorted_run
  end type sorted_work_t

contains

  !> The fields of the slots' particles into s (gather_all), s%src of every slot set first
  !> when there are no images; by every thread of an open team, or in a region of its own.
  subroutine gather_fields(st, s, images)
    type(state_t), intent(inout), target :: st
    type(sorted_t), intent(inout), target :: s
    logical, intent(in) :: images
    type(sorted_work_t) :: work
    work%st => st
    work%s => s
    work%images = images
    call in_team(work, GATHER)
  end subroutine gather_fields

  subroutine sorted_run(self, which)
    class(sorted_work_t), intent(inout) :: self
    integer, intent(in) :: which
    select case (which)
    case (GATHER)
      call gather_all(self%st, self%s, self%images)
    case default
      call scatter_all(self%s, self%st, self%xsph_eps, self%shifted)
    end select
  end subroutine sorted_run

  !> The fields of the source particles s%src(1:s%n) into the slots of s, an image's x and u
  !> times its sign and its z shifted (build_imaged, list_rebuild.f90), and zero sums. One
  !> field at a time: each loop's scattered reads then fall in one source array, small enough
  !> to stay in the second-level cache, instead of ten at once. Same values as slot by slot.
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
  !> xsph_eps times the XSPH sums, plus s%shift where shifted (numerics.shifting, set by the
  !> surface tension's passes of the same evaluation); inactive particles get zero rates. The sorted slots are
  !> exactly the active particles, so the two loops write disjoint entries and need no
  !> barrier between them (nowait). Image slots are not scattered: their sums are discarded.
  subroutine scatter_rates(s, st, xsph_eps, shifted)
    type(sorted_t), intent(in), target :: s
    type(state_t), intent(inout), target :: st
    real(rp), intent(in) :: xsph_eps
    logical, intent(in) :: shifted
    type(sorted_work_t) :: work
    work%s => s
    work%st => st
    work%xsph_eps = xsph_eps
    work%shifted = shifted
    call in_team(work, SCATTER)
  end subroutine scatter_rates

  !> The loops of scatter_rates (in_team's SCATTER): every thread its static share of the
  !> slots, a slot's five sums (side by side in rate) back to particle order in one pass;
  !> inactive particles get zeros. Image slots (grid%order(k) > st%n) are skipped.
  subroutine scatter_all(s, st, xsph_eps, shifted)
    type(sorted_t), intent(in) :: s
    type(state_t), intent(inout) :: st
    real(rp), intent(in) :: xsph_eps
    logical, intent(in) :: shifted
    integer :: i
    call scatter_slots(s%n, s%grid%order, st%n, xsph_eps, s%rate, st%ax, st%az, st%ar, &
                       st%xsph_u, st%xsph_w)
    ! the same static share of the slots as scatter_slots' (no barrier needed between them)
    if (shifted) call add_shift(s%n, s%grid%order, st%n, s%shift, st%xsph_u, st%xsph_w)
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

  !> The shifting velocity of the real slots added to their particles' XSPH velocity; by every
  !> thread of a parallel region, the slots shared as in scatter_slots; no wait at the end.
  subroutine add_shift(n, order, n_state, shift, xu, xw)
    integer, intent(in) :: n, order(*), n_state
    real(rp), intent(in) :: shift(2, *)
    real(rp), intent(inout) :: xu(*), xw(*)
    integer :: k, i
    !$omp do schedule(static)
    do k = 1, n
      i = order(k)
      if (i > n_state) cycle
      xu(i) = xu(i) + shift(1, k)
      xw(i) = xw(i) + shift(2, k)
    end do
    !$omp end do nowait
  end subroutine add_shift

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
    if (allocated(s%claims)) then
      if (size(s%claims, 2) < nt) deallocate(s%claims)
    end if
    if (.not. allocated(s%claims)) allocate(s%claims(0:1, nt), source=0_8)
    if (allocated(s%part_na)) then
      if (size(s%part_na) < nt) deallocate(s%part_na, s%part_d2, s%part_same)
    end if
    if (.not. allocated(s%part_na)) allocate(s%part_na(nt), s%part_d2(nt), s%part_same(nt))
  end subroutine thread_lists

  !> Room for n slots and n_all build positions in s.
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
