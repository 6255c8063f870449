!> The axisymmetric mode's part of the rates (physics/axisymmetric.f90), on top of the planar
!> pair sweep of rates.f90, which leaves the pressure out in this mode (sorted order, real
!> slots only). One sweep over the pairs with a fluid particle, images included:
!>   continuity   drho_a/dt = (1/g_a) sum_b mu_b (v_a - v_b) . grad_a W_ab - rho_a (g'_a/g_a) u_a
!>                replaces the planar sum (every real particle: dynamic boundaries too)
!>   pressure     du_a/dt = -sum_b mu_b (P_a/g_a + P_b/g_b) grad_a W_ab + (p_a/rho_a)(g'_a/g_a) e_r
!>                (fluid), the adjoint of the continuity: together they conserve energy
!>   laminar      du_r/dt += nu ((1/r) du_r/dr - u_r / r^2),  du_z/dt += nu (1/r) du_z/dr
!>                (fluid; the radial derivatives from the same sweep over the fluid pairs:
!>                du/dr|_a = sum_b A_b (u_b - u_a) dW_ab/dx_a)
!> Artificial viscosity gets no hoop term: it is numerical damping of the meridian plane,
!> not a model of a physical viscosity. Image slots (order > n_state) are left alone.
!> With domain.axis_pair = "rings" (prm%geometry%axis_pair = AXIS_PAIR_RINGS) the continuity and the
!> pressure are the rings pair's instead (ring_rates; physics/axisymmetric.f90), and the
!> pressure pair's truncation vector, which the CSF force needs, is left in s%axi_dx, s%axi_dz.
!> With prm%geometry%renormalise_continuity (domain.renormalise_ring_continuity) the rings
!> pair's density rate is renormalised along r and z (renormalised_rate), along a jet only up to
!> its intact length (within_reach). With prm%geometry%bound_xsph (domain.bound_ring_xsph) the
!> XSPH sums of the planar sweep are divided by each ring's planar kernel sum sum_b V_b W_ab
!> where it exceeds 1 (ring_rates): near the axis a ring heavier than the first column's counts
!> the planar mass m / (2 pi max(r, h/4)) of a larger area, the sum reaches 2-3.5, and with
!> xsph_eps = 0.5 the correction cancelled or reversed the ring's own velocity, which the
!> pressure then drove without the ring moving (cases/round_jet/README.md, "A ring held at the
!> axis").
module axisymmetric_loops
  use sphjet_kinds, only: rp, pi, VISC_LAMINAR, KERNEL_WENDLAND, AXIS_PAIR_RINGS
  use sphjet_types, only: sph_params_t
  use sphjet_kernels, only: kernel_t, kernel_eval
  use sorted_state, only: sorted_t, R_AX, R_AZ, R_AR, R_XU, R_XW
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID, SWEEP_FRESH, &
                       SWEEP_REUSE
  use axisymmetric, only: mass_per_radian, viscous_hoop, axis_weight_tables, axis_weights, &
                          AXIS_TABLE_N, ring_kernel_tables, ring_kernel_derivs, &
                          RING_NU, RING_NV
  implicit none
  private
  public :: axisymmetric_rates, axis_weights_of

  !> renormalised_rate: the correction is whole where a ring's smaller response is at least
  !> RESPONSE_WHOLE, none below RESPONSE_NONE, linear between; each factor within
  !> [1/FACTOR_MAX, FACTOR_MAX]. The jet's rows need factors of 0.88-1.07 (the surface row
  !> responds 0.51-0.53 radially and 0.62-0.64 axially: h = 2 dx, radial spacing 0.9-1 dx).
  !> The rate so scaled is not the pressure force's adjoint, and in fragments and drops it fed
  !> their motion until the density check stopped the falling jets of the round-jet study's
  !> case (d0/dx 10, gravity): whole at every ring with factors up to 2, the 0.78 m/s jet
  !> started as a column at 43 ms; faded below RESPONSE_WHOLE, at 47 ms (its start-up head)
  !> and the 0.58 m/s one at 87 ms; with factors within 1.25, the 0.58 m/s one at 78 ms (a ring
  !> next to the axis in a drop); with none within h/2 of the axis too (renormalised_rate),
  !> both ran to 250 ms.
  real(rp), parameter :: RESPONSE_WHOLE = 0.5_rp, RESPONSE_NONE = 0.35_rp, FACTOR_MAX = 1.25_rp

  !> The ring kernel's derivative tables per kernel kind, side by side (ring_kernel_tables),
  !> built on first use.
  real(rp), save, allocatable :: ring_tab(:, :, :, :)
  logical, save :: ring_ready(KERNEL_WENDLAND) = .false.

  !> The sums of either pair's sweep: continuity, pressure and, with laminar viscosity, the
  !> radial derivatives (u_b - u_a) F dx, (w_b - w_a) F dx weighted by the partner's area
  !> (planar volume v = m / rho); pg the pressure factor of the pair.
  type, abstract, extends(pair_body_t) :: axi_sums_t
    type(sorted_t), pointer :: s => null()
    logical :: laminar = .false.
    real(rp), allocatable :: v(:), pg(:), cont(:), pax(:), paz(:), dudr(:), dwdr(:)
  contains
    procedure :: start => sums_start
    procedure :: sweep => sums_sweep
    procedure :: accelerate => sums_accelerate
  end type axi_sums_t

  !> The smoothed-radius pair's sweep (axi_pairs), with the masses per radian mu.
  type, extends(axi_sums_t) :: axi_body_t
    real(rp), allocatable :: mu(:)
  contains
    procedure :: visit => axi_visit
  end type axi_body_t

  !> The rings pair's sweep (ring_pairs), with the ring masses m, the ring volumes vr = m/rho
  !> and the truncation vector's sums ddx, ddz; with renorm also the axial part of the
  !> continuity cz and the continuity's moments mr, mz (renormalised_rate); with bound
  !> (bound_xsph) each slot's planar kernel sum but its own term, ks.
  type, extends(axi_sums_t) :: ring_body_t
    integer :: kind = 0
    real(rp) :: h = 0.0_rp
    logical :: renorm = .false.
    real(rp), allocatable :: m(:), vr(:), ddx(:), ddz(:), cz(:), mr(:), mz(:)
    logical :: bound = .false.
    real(rp), allocatable :: ks(:)
    logical, allocatable :: real_(:)
  contains
    procedure :: visit => ring_visit
  end type ring_body_t

  !> Axis weight tables per kernel kind (axis_weight_tables), built on first use.
  real(rp), save :: tab_gi(AXIS_TABLE_N, KERNEL_WENDLAND), tab_hoop(AXIS_TABLE_N, KERNEL_WENDLAND)
  logical, save :: tab_ready(KERNEL_WENDLAND) = .false.

contains

  !> Sets the density rate and adds the pressure (and laminar hoop) accelerations in s%rate
  !> of the real slots. kept (default .false.): visit the pairs the last sweep at these
  !> positions kept (pair_sweep with SWEEP_KEEP, PAIRS_ANY_FLUID: the rates sweep's)
  !> instead of finding them and evaluating the kernel again; the same pairs in the same
  !> order either way.
  subroutine axisymmetric_rates(prm, kern, s, n_state, kept)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    integer, intent(in) :: n_state
    logical, intent(in), optional :: kept
    type(axi_body_t) :: body
    integer :: k, n
    real(rp), allocatable :: gi(:), hoop(:)
    logical :: laminar

    n = s%n
    laminar = prm%viscosity%model == VISC_LAMINAR .and. prm%viscosity%value > 0.0_rp
    if (prm%geometry%axis_pair == AXIS_PAIR_RINGS) then
      call ring_rates(prm, kern, s, n_state, laminar, kept)
      return
    end if
    allocate(gi(n), hoop(n))
    call axis_weights_of(kern, s%x(1:n), gi, hoop)
    call body%start(s, laminar)
    body%mu = mass_per_radian(s%m(1:n), s%x(1:n), prm%numerics%h)
    body%pg = body%pg * gi
    call body%sweep(kern, kept)
    !$omp parallel do schedule(static)
    do k = 1, n
      if (s%grid%order(k) > n_state) cycle
      s%rate(R_AR, k) = body%cont(k) * gi(k) - s%rho(k) * hoop(k) * s%u(k)
      if (s%fluid(k)) call body%accelerate(prm, k, s%p(k) / s%rho(k) * hoop(k))
    end do
    !$omp end parallel do
  end subroutine axisymmetric_rates

  !> The rings pair (physics/axisymmetric.f90, ring_kernel_tables): the 3D SPH density of the
  !> rings rho_a = sum_b m_b Wr_ab (a itself included: its own far side), its continuity and
  !> Euler-Lagrange force; pairs with a mirror image are skipped (the ring kernel holds the far
  !> side of each ring), periodic images are not. The lattice's error at the axis is the
  !> midpoint rule's, (dx^2/24) F'(0) per row of rings (Euler-Maclaurin, F = 2 pi r f): to that
  !> order the first column's rings (r = dx/2, ring mass pi rho0 dx^2 dz, the next column's 3
  !> times that: told by a mass below prm%geometry%axis_m1 = 2 pi rho0 dx^2 dz) count with 11/12 of
  !> their mass in every sum of the pair (so that it still conserves its energy, with that
  !> mass as the rings' inertia in it). prm%geometry%axis_m1 = 0 leaves the masses alone.
  subroutine ring_rates(prm, kern, s, n_state, laminar, kept)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    integer, intent(in) :: n_state
    logical, intent(in) :: laminar
    logical, intent(in), optional :: kept
    type(ring_body_t) :: body
    integer :: k, n
    real(rp) :: fs, fp, self, w0, f0, ksum
    n = s%n
    !$omp critical (ring_tables_cache)
    if (.not. allocated(ring_tab)) allocate(ring_tab(2, RING_NU, RING_NV, KERNEL_WENDLAND))
    if (.not. ring_ready(kern%kind)) then
      call ring_kernel_tables(kern%kind, ring_tab(:, :, :, kern%kind))
      ring_ready(kern%kind) = .true.
    end if
    !$omp end critical (ring_tables_cache)
    call body%start(s, laminar)
    body%m = 2.0_rp * pi * mass_per_radian(s%m(1:n), s%x(1:n), prm%numerics%h)
    ! the midpoint rule's end correction at the axis (above)
    where (body%m < prm%geometry%axis_m1) body%m = body%m * (11.0_rp / 12.0_rp)
    body%vr = body%m / s%rho(1:n)
    body%real_ = sign(1.0_rp, s%x(1:n)) > 0.0_rp   ! not an axis image
    allocate(body%ddx(n), body%ddz(n), source=0.0_rp)
    body%renorm = prm%geometry%renormalise_continuity /= 0
    ! the renormalisation's sums (size 1, untouched, without it)
    allocate(body%cz(merge(n, 1, body%renorm)), body%mr(merge(n, 1, body%renorm)), &
             body%mz(merge(n, 1, body%renorm)), source=0.0_rp)
    body%kind = kern%kind
    body%h = prm%numerics%h
    body%bound = prm%geometry%bound_xsph /= 0
    allocate(body%ks(merge(n, 1, body%bound)), source=0.0_rp)
    call body%sweep(kern, kept)
    if (body%bound) then
      ! the planar XSPH sums of the rates' sweep (rates.f90) over max(1, the slot's kernel sum)
      call kernel_eval(kern, 0.0_rp, w0, f0)
      !$omp parallel do schedule(static) private(ksum)
      do k = 1, n
        ksum = body%ks(k) + body%v(k) * w0
        if (ksum > 1.0_rp) s%rate(R_XU:R_XW, k) = s%rate(R_XU:R_XW, k) / ksum
      end do
      !$omp end parallel do
    end if
    if (allocated(s%axi_dx)) then
      if (size(s%axi_dx) < n) deallocate(s%axi_dx, s%axi_dz)
    end if
    if (.not. allocated(s%axi_dx)) allocate(s%axi_dx(n + n / 4 + 16), s%axi_dz(n + n / 4 + 16))
    !$omp parallel do schedule(static) private(fs, fp, self)
    do k = 1, n
      s%axi_dx(k) = 0.0_rp
      s%axi_dz(k) = 0.0_rp
      if (s%grid%order(k) > n_state) cycle
      ! the ring's own far side: dWr(0, r^2)/dr = 2 r Fp
      call ring_kernel_derivs(0.0_rp, s%x(k)**2, prm%numerics%h, ring_tab(:, :, :, kern%kind), &
                              fs, fp)
      self = 2.0_rp * s%x(k) * fp
      s%rate(R_AR, k) = body%cont(k) + body%m(k) * s%u(k) * self
      if (body%renorm) s%rate(R_AR, k) = renormalised_rate(s%rate(R_AR, k), body%cz(k), &
                                                           body%mr(k) + body%m(k) * s%x(k) * self, &
                                                           body%mz(k), s%rho(k), s%x(k) / prm%numerics%h, &
                                                           within_reach(prm, s%x(k), s%z(k)))
      s%axi_dx(k) = body%ddx(k) + body%vr(k) * self
      s%axi_dz(k) = body%ddz(k)
      if (s%fluid(k)) call body%accelerate(prm, k, -(body%pg(k) * body%m(k) * self))
    end do
    !$omp end parallel do
  end subroutine ring_rates

  !> Readies the common sums for a sweep over the slots of s: v = m/rho, pg = p/rho^2 (a pair
  !> may weight it), the sums zero.
  subroutine sums_start(self, s, laminar)
    class(axi_sums_t), intent(inout) :: self
    type(sorted_t), intent(inout), target :: s
    logical, intent(in) :: laminar
    integer :: n
    n = s%n
    allocate(self%cont(n), self%pax(n), self%paz(n), self%dudr(n), self%dwdr(n), source=0.0_rp)
    self%v = s%m(1:n) / s%rho(1:n)
    self%pg = s%pr(1:n)
    self%laminar = laminar
    self%s => s
  end subroutine sums_start

  !> The sweep over the pairs with a fluid particle, images included. kept: the pairs the
  !> last sweep at these positions kept (axisymmetric_rates).
  subroutine sums_sweep(self, kern, kept)
    class(axi_sums_t), intent(inout) :: self
    type(kernel_t), intent(in) :: kern
    logical, intent(in), optional :: kept
    integer :: how
    real(rp) :: red
    red = 0.0_rp
    how = SWEEP_FRESH
    if (present(kept)) how = merge(SWEEP_REUSE, SWEEP_FRESH, kept)
    call pair_sweep(self%s, kern, PAIRS_ANY_FLUID, self, red, how)
  end subroutine sums_sweep

  !> The pairs of one row task: the rings pair's sums (ring_pairs).
  subroutine ring_visit(self, pl, red)
    class(ring_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    call ring_pairs(self%laminar, pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, self%s%x, self%s%u, &
                    self%s%w, self%s%fluid, self%real_, self%h, ring_tab(:, :, :, self%kind), &
                    self%m, self%v, self%vr, self%pg, self%cont, &
                    self%pax, self%paz, self%dudr, self%dwdr, self%ddx, self%ddz, &
                    self%renorm, self%cz, self%mr, self%mz, self%bound, pl%w, self%ks)
    red = max(red, 0.0_rp)
  end subroutine ring_visit

  !> The rings pair's sums over the pairs of one list: pairs of two rings (no mirror image)
  !> add to the continuity, the pressure and the truncation vector with the ring kernel's
  !> derivatives (dWr/dr_a = 2 (r_a - r_b) Fs + r_b Fp, dWr/dz_a = 2 (z_a - z_b) Fs); fluid
  !> pairs, images included, to the radial velocity derivatives as axi_pairs. renorm: the
  !> continuity's axial part to cz and its moments to mr (its rate for u = r, w = 0) and mz
  !> (for u = 0, w = z) as well. bound: every pair, images included, to the planar kernel sums ks
  !> (the planar volumes v, the kernel values wk).
  pure subroutine ring_pairs(laminar, np, pa, pb, dx, dz, f, x, u, w, fl, rl, h, tab, m, v, &
                             vr, pg, cont, pax, paz, dudr, dwdr, ddx, ddz, renorm, cz, mr, mz, bound, &
                             wk, ks)
    logical, intent(in) :: laminar
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), f(*), x(*), u(*), w(*), m(*), v(*), vr(*), pg(*), h
    real(rp), intent(in) :: tab(2, RING_NU, RING_NV)
    logical, intent(in) :: fl(*), rl(*)
    real(rp), intent(inout) :: cont(*), pax(*), paz(*), dudr(*), dwdr(*), ddx(*), ddz(*)
    logical, intent(in) :: renorm
    real(rp), intent(inout) :: cz(*), mr(*), mz(*)
    logical, intent(in) :: bound
    real(rp), intent(in) :: wk(*)
    real(rp), intent(inout) :: ks(*)
    integer :: k, a, b
    real(rp) :: q, t, fs, fp, dra, drb, dzz, qz, qr, qm
    real(rp), allocatable :: fsk(:), fpk(:)   ! on the heap: a row's pair list may be long
    ! The kernel's derivatives first, in a loop of their own: each reads a cell of the 1 MB
    ! table at a place no earlier pair predicts, and a short loop keeps many of those reads in
    ! flight at once, where the sums' long body would wait for each (the same operations, so
    ! the same numbers).
    allocate(fsk(np), fpk(np))
    do k = 1, np
      a = pa(k)
      b = pb(k)
      if (rl(a) .and. rl(b)) &
        call ring_kernel_derivs(dx(k)**2 + dz(k)**2, x(a) * x(b), h, tab, fsk(k), fpk(k))
    end do
    do k = 1, np
      a = pa(k)
      b = pb(k)
      if (rl(a) .and. rl(b)) then
        fs = fsk(k)
        fp = fpk(k)
        dra = 2.0_rp * dx(k) * fs + x(b) * fp
        drb = -2.0_rp * dx(k) * fs + x(a) * fp
        dzz = 2.0_rp * dz(k) * fs
        q = u(a) * dra + u(b) * drb + (w(a) - w(b)) * dzz
        cont(a) = cont(a) + m(b) * q
        cont(b) = cont(b) + m(a) * q
        if (renorm) then
          qz = (w(a) - w(b)) * dzz
          cz(a) = cz(a) + m(b) * qz
          cz(b) = cz(b) + m(a) * qz
          qr = x(a) * dra + x(b) * drb   ! q with u = r, w = 0
          mr(a) = mr(a) + m(b) * qr
          mr(b) = mr(b) + m(a) * qr
          qm = dz(k) * dzz               ! q with u = 0, w = z
          mz(a) = mz(a) + m(b) * qm
          mz(b) = mz(b) + m(a) * qm
        end if
        t = pg(a) + pg(b)
        pax(a) = pax(a) - m(b) * t * dra
        paz(a) = paz(a) - m(b) * t * dzz
        pax(b) = pax(b) - m(a) * t * drb
        paz(b) = paz(b) + m(a) * t * dzz
        if (fl(a) .and. fl(b)) then
          ddx(a) = ddx(a) + 2.0_rp * vr(b) * dra
          ddz(a) = ddz(a) + 2.0_rp * vr(b) * dzz
          ddx(b) = ddx(b) + 2.0_rp * vr(a) * drb
          ddz(b) = ddz(b) - 2.0_rp * vr(a) * dzz
        end if
      end if
      if (laminar .and. fl(a) .and. fl(b)) &
        call add_radial_derivatives(a, b, f(k) * dx(k), u, w, v, dudr, dwdr)
      if (bound) then   ! the planar kernel sum, images included (as the XSPH sums)
        ks(a) = ks(a) + v(b) * wk(k)
        ks(b) = ks(b) + v(a) * wk(k)
      end if
    end do
  end subroutine ring_pairs

  !> The rings pair's density rate c (its radial part c - cz, its axial part cz) renormalised
  !> along r and z. The ring's own sums give its response to a radial stretch u = r, mr, and
  !> to an axial one w = z, mz: in the bulk of a lattice -2 rho and -rho; where the surface
  !> cuts the kernel less, and less radially than axially (the surface row of a five-ring
  !> column 0.53 and 0.64 of the bulk's, h = 2 dx). So a stretch that keeps the volume, as
  !> along a falling jet, changed the outer rows' density (the surface row's by -0.11 rho times
  !> the axial strain), and the rows moved to put it back: the inner rows fell behind the
  !> jet's contraction, then buckled. Here each part is scaled so that both respond as their
  !> volume-weighted mean (2 er + ez) / 3 (er, ez the responses over the bulk's): a stretch
  !> without a change of volume leaves the density alone, a change of volume changes it as
  !> before. Faded out below a response of RESPONSE_WHOLE (module header), and towards the axis
  !> from h to h/2 (x_over_h = r/h), none closer: the rings there respond as the bulk's (the
  !> five-ring column's two inner rows within 0.6%), and in drops they are the ones that move
  !> fastest. reach: the weight of the ring's place along a jet (within_reach), 0 to 1.
  pure function renormalised_rate(c, cz, mr, mz, rho, x_over_h, reach) result(r)
    real(rp), intent(in) :: c, cz, mr, mz, rho, x_over_h, reach
    real(rp) :: r, er, ez, eb, fr, fz, lam
    er = mr / (-2.0_rp * rho)
    ez = mz / (-rho)
    r = c
    if (er <= 0.0_rp .or. ez <= 0.0_rp) return
    lam = min(1.0_rp, max(0.0_rp, (min(er, ez) - RESPONSE_NONE) / (RESPONSE_WHOLE - RESPONSE_NONE)))
    lam = lam * min(1.0_rp, max(0.0_rp, 2.0_rp * x_over_h - 1.0_rp))   ! none within h/2 of the axis
    lam = lam * reach
    if (lam <= 0.0_rp) return
    eb = (2.0_rp * er + ez) / 3.0_rp
    fr = 1.0_rp + lam * (min(FACTOR_MAX, max(1.0_rp / FACTOR_MAX, eb / er)) - 1.0_rp)
    fz = 1.0_rp + lam * (min(FACTOR_MAX, max(1.0_rp / FACTOR_MAX, eb / ez)) - 1.0_rp)
    r = fr * (c - cz) + fz * cz
  end function renormalised_rate

  !> The renormalisation's weight at (x, z) along a jet: with prm%geometry%renormalise_reach =
  !> L > 0 (the driver's: the jet's intact length at its latest breakup check) 1 nearer the
  !> orifice than L - 2h along the nozzle's axis, 0 beyond L, linear between; 1 everywhere with
  !> L <= 0. The key is for the jet's stretching lattice. A drop falls as it would without
  !> gravity and holds no such lattice, and there the scaled rate only breaks the pair's energy
  !> balance: with the key on every ring the falling round-jet study (d0/dx 10, column starts)
  !> stopped on the density check in 3 of its 20 runs, each at rings gathered at the axis of a
  !> drop past the jet's end; along the jet only, in none (cases/round_jet/README.md, "The
  !> falling study"). Those stops were measured before the rings that cross the axis were
  !> reflected ahead of the rates (5dfe57e), which alone gathered rings at a drop's axis; the
  !> key on every ring has not been measured since.
  pure real(rp) function within_reach(prm, x, z)
    type(sph_params_t), intent(in) :: prm
    real(rp), intent(in) :: x, z
    real(rp) :: s
    within_reach = 1.0_rp
    if (.not. prm%geometry%renormalise_reach > 0.0_rp) return
    s = (x - prm%nozzle%x0) * prm%nozzle%ex + (z - prm%nozzle%z0) * prm%nozzle%ez
    within_reach = min(1.0_rp, max(0.0_rp, (prm%geometry%renormalise_reach - s) / (2.0_rp * prm%numerics%h)))
  end function within_reach

  !> The axis weights 1/g and g'/g of every x (physics/axisymmetric.f90: axis_weights), from
  !> the kernel's tables (built once per kind).
  subroutine axis_weights_of(kern, x, gi, hoop)
    type(kernel_t), intent(in) :: kern
    real(rp), intent(in) :: x(:)
    real(rp), intent(out) :: gi(:), hoop(:)
    integer :: k
    !$omp critical (axis_weight_tables_cache)
    if (.not. tab_ready(kern%kind)) then
      call axis_weight_tables(kern%kind, tab_gi(:, kern%kind), tab_hoop(:, kern%kind))
      tab_ready(kern%kind) = .true.
    end if
    !$omp end critical (axis_weight_tables_cache)
    do k = 1, size(x)
      call axis_weights(x(k), kern%h, tab_gi(:, kern%kind), tab_hoop(:, kern%kind), gi(k), hoop(k))
    end do
  end subroutine axis_weights_of

  !> The pairs of one row task: the axisymmetric pressure pair, continuity and velocity
  !> gradients (axi_pairs).
  subroutine axi_visit(self, pl, red)
    class(axi_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    call axi_pairs(self%laminar, pl%n, pl%a, pl%b, pl%dx, pl%dz, pl%f, self%s%u, self%s%w, &
                   self%s%fluid, self%mu, self%v, self%pg, self%cont, self%pax, self%paz, &
                   self%dudr, self%dwdr)
    red = max(red, 0.0_rp)
  end subroutine axi_visit

  !> The sums of the sweep over the pairs of one list. Plain arrays, so that the loop keeps
  !> their addresses in registers.
  pure subroutine axi_pairs(laminar, np, pa, pb, dx, dz, f, u, w, fl, mu, v, pg, cont, pax, &
                            paz, dudr, dwdr)
    logical, intent(in) :: laminar
    integer, intent(in) :: np, pa(*), pb(*)
    real(rp), intent(in) :: dx(*), dz(*), f(*), u(*), w(*), mu(*), v(*), pg(*)
    logical, intent(in) :: fl(*)
    real(rp), intent(inout) :: cont(*), pax(*), paz(*), dudr(*), dwdr(*)
    integer :: k, a, b
    real(rp) :: gx, gz, q, t
    do k = 1, np
      a = pa(k)
      b = pb(k)
      gx = f(k) * dx(k)
      gz = f(k) * dz(k)
      ! continuity: a gets mu_b v_ab . grad_a W_ab, b mu_a v_ab . grad_a W_ab
      q = (u(a) - u(b)) * gx + (w(a) - w(b)) * gz
      cont(a) = cont(a) + mu(b) * q
      cont(b) = cont(b) + mu(a) * q
      ! pressure: a gets -mu_b (P_a/g_a + P_b/g_b) grad_a W_ab, b the opposite with mu_a
      t = pg(a) + pg(b)
      pax(a) = pax(a) - mu(b) * t * gx
      paz(a) = paz(a) - mu(b) * t * gz
      pax(b) = pax(b) + mu(a) * t * gx
      paz(b) = paz(b) + mu(a) * t * gz
      if (laminar .and. fl(a) .and. fl(b)) &
        call add_radial_derivatives(a, b, gx, u, w, v, dudr, dwdr)
    end do
  end subroutine axi_pairs

  !> The radial derivatives of u_r and u_z of a fluid pair (a, b) with gx = dW_ab/dx_a = F dx:
  !> du/dr|_a += A_b (u_b - u_a) gx, and b the same (dW_ba/dx_b = -gx, u_a - u_b = -(u_b - u_a)).
  pure subroutine add_radial_derivatives(a, b, gx, u, w, v, dudr, dwdr)
    integer, intent(in) :: a, b
    real(rp), intent(in) :: gx, u(*), w(*), v(*)
    real(rp), intent(inout) :: dudr(*), dwdr(*)
    real(rp) :: du, dw
    du = u(b) - u(a)
    dw = w(b) - w(a)
    dudr(a) = dudr(a) + v(b) * du * gx
    dwdr(a) = dwdr(a) + v(b) * dw * gx
    dudr(b) = dudr(b) + v(a) * du * gx
    dwdr(b) = dwdr(b) + v(a) * dw * gx
  end subroutine add_radial_derivatives

  !> Adds to fluid slot k's acceleration its pressure sums, fx (the pair's own radial force
  !> of the slot alone: its hoop term) and, with laminar viscosity, the viscous hoop terms
  !> (physics/axisymmetric.f90, viscous_hoop) from its radial derivatives.
  subroutine sums_accelerate(self, prm, k, fx)
    class(axi_sums_t), intent(in) :: self
    type(sph_params_t), intent(in) :: prm
    integer, intent(in) :: k
    real(rp), intent(in) :: fx
    real(rp) :: hx, hz
    associate (s => self%s)
      s%rate(R_AX, k) = s%rate(R_AX, k) + self%pax(k) + fx
      s%rate(R_AZ, k) = s%rate(R_AZ, k) + self%paz(k)
      if (self%laminar) then
        call viscous_hoop(prm%viscosity%value, s%u(k), self%dudr(k), self%dwdr(k), s%x(k), prm%numerics%h, &
                          hx, hz)
        s%rate(R_AX, k) = s%rate(R_AX, k) + hx
        s%rate(R_AZ, k) = s%rate(R_AZ, k) + hz
      end if
    end associate
  end subroutine sums_accelerate

end module axisymmetric_loops
