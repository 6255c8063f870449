!> The surface-energy force (surface_tension.model = "energy"; physics/surface_energy.f90) over
!> the sorted particles: two sweeps over the fluid pairs, the colour gradient g, then the pair
!> force with the kernel's Hessian, and the acceleration added to s%rate (rows R_AX, R_AZ) of the
!> real fluid slots. Boundary particles do not enter, as in the CSF force: a wall counts as "not
!> liquid". Image slots (axis, periodic z) take their sources' g between the sweeps, the radial
!> part mirrored, so that the sums over images are those of the mirrored or shifted liquid.
!> Bitwise independent of the thread count, like every traversal here.
module surface_energy_loops
  use sphjet_kinds, only: rp, GEOM_AXISYMMETRIC
  use sphjet_types, only: sph_params_t
  use sphjet_kernels, only: kernel_t, kernel_d2, kernel_eval
  use sorted_state, only: sorted_t, R_AX, R_AZ
  use particle_images, only: copy_to_images
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_FLUID, SWEEP_FRESH
  use axisymmetric, only: axis_radius
  use surface_energy, only: surface_energy_kappa, hessian_times, energy_density, area_eps, read_switch, no_pi
  implicit none
  private
  public :: surface_energy_rates

  integer, parameter :: PASS_GRADIENT = 1, PASS_FORCE = 2, PASS_TENSION = 3

  !> Per-slot fields (sorted order): planar area v = m/rho, energy weight w (1, or the ring's
  !> radius), colour gradient g and the pair force's sums f = -sum_b V_b H_kb (w_k g_k - w_b g_b).
  type :: se_work_t
    real(rp), allocatable :: v(:), w(:), gx(:), gz(:), fx(:), fz(:)
    !> sum_a w_a V_a g_a . grad_a W_ak, then the surface tension pi_k / rho_k^2 (pressure units
    !> over rho^2) and the planar masses
    real(rp), allocatable :: sg(:), pt(:), m(:), tx(:), tz(:), rt(:), qx(:), qz(:), ph(:)
    real(rp) :: inv_wdp = 0.0_rp
  end type se_work_t

  type, extends(pair_body_t) :: se_body_t
    integer :: pass = PASS_GRADIENT
    type(kernel_t) :: kern
    type(se_work_t), pointer :: wk => null()
  contains
    procedure :: visit => se_visit
  end type se_body_t

  !> kappa_s of the last (kernel, h, dx) asked for.
  real(rp), save :: kappa_cached = 0.0_rp, h_cached = -1.0_rp, dx_cached = -1.0_rp
  integer, save :: kind_cached = -1

contains

  !> Adds the surface-energy acceleration of every real fluid slot to s%rate. s holds the
  !> gathered state and its neighbour list (gather_sorted).
  subroutine surface_energy_rates(prm, kern, s)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout) :: s
    type(se_work_t), target :: wk
    type(se_body_t) :: body
    real(rp) :: red, coef, kap, hoop
    integer :: n, k
    logical :: axi

    n = s%n
    axi = prm%geometry%kind == GEOM_AXISYMMETRIC
    !$omp critical (surface_energy_kappa_cache)
    if (kind_cached /= kern%kind .or. h_cached /= kern%h .or. dx_cached /= prm%surface_tension%dx) then
      call read_switch()
      kappa_cached = surface_energy_kappa(kern, prm%surface_tension%dx, area_eps / kern%h)
      kind_cached = kern%kind
      h_cached = kern%h
      dx_cached = prm%surface_tension%dx
    end if
    kap = kappa_cached
    !$omp end critical (surface_energy_kappa_cache)
    allocate(wk%v(n), wk%w(n), wk%gx(n), wk%gz(n), wk%fx(n), wk%fz(n), wk%sg(n), wk%pt(n), wk%m(n), wk%tx(n), wk%tz(n), wk%rt(n), wk%qx(n), wk%qz(n), wk%ph(n))
    !$omp parallel do schedule(static)
    do k = 1, n
      wk%v(k) = s%m(k) / s%rho(k)
      if (no_pi) wk%v(k) = s%m(k) / prm%eos%rho0
      wk%w(k) = 1.0_rp
      if (axi) wk%w(k) = axis_radius(s%x(k), prm%numerics%h)
      wk%gx(k) = 0.0_rp
      wk%gz(k) = 0.0_rp
      wk%fx(k) = 0.0_rp
      wk%fz(k) = 0.0_rp
      wk%sg(k) = 0.0_rp
      wk%m(k) = s%m(k)
      wk%tx(k) = 0.0_rp
      wk%tz(k) = 0.0_rp
    end do
    !$omp end parallel do

    body%kern = kern
    body%wk => wk
    red = 0.0_rp
    body%pass = PASS_GRADIENT
    call pair_sweep(s, kern, PAIRS_FLUID, body, red, SWEEP_FRESH)
    if (s%n > s%n_real) then
      call copy_to_images(s, wk%gx, .true.)
      call copy_to_images(s, wk%gz, .false.)
    end if
    ! Phi(g) and q = dPhi/dg (image slots included: they have their sources' g)
    !$omp parallel do schedule(static)
    do k = 1, n
      call energy_density(wk%gx(k), wk%gz(k), area_eps / kern%h, wk%ph(k), wk%qx(k), wk%qz(k))
    end do
    !$omp end parallel do
    body%pass = PASS_FORCE
    call pair_sweep(s, kern, PAIRS_FLUID, body, red, SWEEP_FRESH)

    coef = prm%surface_tension%sigma * kap
    ! the energy's dependence on the densities: a tension pi_k = -(rho_k^2/M_k) dE/drho_k =
    ! -sigma kappa_s (w_k |g_k|^2 + 2 sum_a w_a V_a g_a . grad_a W_ak) / w_k, applied as a pressure
    !$omp parallel do schedule(static)
    do k = 1, n
      wk%pt(k) = -coef * (wk%w(k) * wk%ph(k) + wk%sg(k)) / wk%w(k) / s%rho(k)**2
      wk%rt(k) = 0.2_rp * max(-(s%p(k) / s%rho(k)**2 + wk%pt(k)), 0.0_rp)
    end do
    !$omp end parallel do
    if (s%n > s%n_real) call copy_to_images(s, wk%pt, .false.)
    if (s%n > s%n_real) call copy_to_images(s, wk%rt, .false.)
    block
      real(rp) :: wdp, fdp
      call kernel_eval(kern, prm%surface_tension%dx, wdp, fdp)
      wk%inv_wdp = 1.0_rp / wdp
    end block
    body%pass = PASS_TENSION
    if (.not. no_pi) call pair_sweep(s, kern, PAIRS_FLUID, body, red, SWEEP_FRESH)
    !$omp parallel do schedule(static) private(hoop)
    do k = 1, s%n_real
      if (.not. s%fluid(k)) cycle
      hoop = 0.0_rp
      if (axi .and. abs(s%x(k)) > 0.25_rp * prm%numerics%h) &
        hoop = sign(1.0_rp, s%x(k)) * wk%ph(k)
      s%rate(R_AX, k) = s%rate(R_AX, k) + coef / (s%rho(k) * wk%w(k)) * (wk%fx(k) - hoop) + wk%tx(k)
      s%rate(R_AZ, k) = s%rate(R_AZ, k) + coef / (s%rho(k) * wk%w(k)) * wk%fz(k) + wk%tz(k)
    end do
    !$omp end parallel do
  end subroutine surface_energy_rates

  subroutine se_visit(self, pl, red)
    class(se_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: p, a, b
    real(rp) :: d2, ux, uz, hx, hz
    associate (wk => self%wk)
      if (self%pass == PASS_GRADIENT) then
        do p = 1, pl%n
          a = pl%a(p)
          b = pl%b(p)
          wk%gx(a) = wk%gx(a) + wk%v(b) * pl%f(p) * pl%dx(p)
          wk%gz(a) = wk%gz(a) + wk%v(b) * pl%f(p) * pl%dz(p)
          wk%gx(b) = wk%gx(b) - wk%v(a) * pl%f(p) * pl%dx(p)
          wk%gz(b) = wk%gz(b) - wk%v(a) * pl%f(p) * pl%dz(p)
        end do
      else if (self%pass == PASS_FORCE) then
        do p = 1, pl%n
          a = pl%a(p)
          b = pl%b(p)
          d2 = kernel_d2(self%kern, sqrt(pl%r2(p)))
          ux = wk%w(a) * wk%qx(a) - wk%w(b) * wk%qx(b)
          uz = wk%w(a) * wk%qz(a) - wk%w(b) * wk%qz(b)
          call hessian_times(pl%f(p), d2, pl%dx(p), pl%dz(p), pl%r2(p), ux, uz, hx, hz)
          wk%fx(a) = wk%fx(a) - wk%v(b) * hx
          wk%fz(a) = wk%fz(a) - wk%v(b) * hz
          wk%fx(b) = wk%fx(b) + wk%v(a) * hx
          wk%fz(b) = wk%fz(b) + wk%v(a) * hz
          ! grad_a W_ab = F (x_a - x_b): s_b gets a's term, s_a b's
          wk%sg(b) = wk%sg(b) + wk%w(a) * wk%v(a) * pl%f(p) * (wk%qx(a) * pl%dx(p) + wk%qz(a) * pl%dz(p))
          wk%sg(a) = wk%sg(a) - wk%w(b) * wk%v(b) * pl%f(p) * (wk%qx(b) * pl%dx(p) + wk%qz(b) * pl%dz(p))
        end do
      else   ! the tension's pressure pair, in the force sums f (accelerations)
        do p = 1, pl%n
          a = pl%a(p)
          b = pl%b(p)
          hx = (wk%pt(a) + wk%pt(b) + (wk%rt(a) + wk%rt(b)) * (pl%w(p) * wk%inv_wdp)**4) * pl%f(p)
          wk%tx(a) = wk%tx(a) - wk%m(b) * hx * pl%dx(p)
          wk%tz(a) = wk%tz(a) - wk%m(b) * hx * pl%dz(p)
          wk%tx(b) = wk%tx(b) + wk%m(a) * hx * pl%dx(p)
          wk%tz(b) = wk%tz(b) + wk%m(a) * hx * pl%dz(p)
        end do
      end if
    end associate
    red = red + 0.0_rp
  end subroutine se_visit

end module surface_energy_loops
