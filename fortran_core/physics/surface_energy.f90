!> Surface tension as a surface energy (surface_tension.model = "energy"): the force is minus
!> the gradient of a discrete surface energy, so that it can only turn that energy into motion
!> and never feed a disturbance from nowhere (the CSF force, not being the gradient of anything,
!> can: cases/round_jet/README.md). The energy is a gradient energy of the particles' colour,
!>   E = sigma kappa_s sum_a w_a V_a |g_a|^2,   g_a = sum_b V_b grad_a W_ab (fluid b, b /= a),
!> g the colour gradient (zero in a full support, about n / (width) at a free surface), V = m/rho
!> the particle's planar area, w = 1 (planar: E per unit depth) or the ring's radius
!> (axisymmetric: E / 2 pi, the surface's area weighted by r), and kappa_s the length that makes a
!> flat free surface of the square lattice hold sigma per unit area (surface_energy_kappa). With V
!> held, the force on particle k is
!>   F_k = -dE/dx_k = -sigma kappa_s V_k [ w'_k |g_k|^2 e_r + 2 sum_b V_b H_kb (w_k g_k - w_b g_b) ],
!> H_kb = grad grad W(x_k - x_b) the kernel's Hessian (hessian_times): a pair force, equal and
!> opposite on k and b, plus the ring's hoop term w' |g|^2 (w' = 1 off the axis bound), which
!> holds the azimuthal curvature. The acceleration is F_k / (rho_k w_k V_k). A uniform
!> displacement of every particle leaves E unchanged, so the pair sums balance: the net force of
!> a flat surface on its rows is zero and a column's is its Laplace pressure sigma / a.
module surface_energy
  use sphjet_kinds, only: rp
  use sphjet_kernels, only: kernel_t, kernel_eval
  implicit none
  private
  public :: surface_energy_kappa, hessian_times, energy_density, area_eps, read_switch, no_pi
  logical, save :: no_pi = .false.
  real(rp), save :: area_eps = -1.0_rp   ! experiment: < 0 gradient energy, else eps h of the area form

contains

  !> kappa_s [m]: 1 / (dx sum_j |g_j|^2) over the rows j of a flat free surface of the square
  !> lattice of spacing dx (rows at depth j dx, j >= 0, every column filled), so that the energy
  !> per unit length of that surface is sigma.
  function surface_energy_kappa(kern, dx, eps) result(kappa)
    type(kernel_t), intent(in) :: kern
    real(rp), intent(in) :: dx, eps
    real(rp) :: kappa, gz, r, w, f, total, ph, qx, qz
    integer :: nr, i, j, k
    nr = ceiling(2.0_rp * kern%h / dx) + 1
    total = 0.0_rp
    do j = 0, nr   ! the particle at (0, -j dx); the fluid fills z <= 0
      gz = 0.0_rp
      do k = 0, j + nr
        do i = -nr, nr
          if (i == 0 .and. k == j) cycle
          r = dx * sqrt(real(i * i + (k - j) * (k - j), rp))
          if (r >= 2.0_rp * kern%h) cycle
          call kernel_eval(kern, r, w, f)
          gz = gz + dx * dx * f * real(k - j, rp) * dx   ! z_a - z_b = (k - j) dx
        end do
      end do
      call energy_density(0.0_rp, gz, eps, ph, qx, qz)
      total = total + ph   ! the x part cancels by symmetry
    end do
    kappa = 1.0_rp / (dx * total)
  end function surface_energy_kappa

  subroutine read_switch()
    character(len=32) :: v
    integer :: st
    call get_environment_variable("SPHJET_SE_AREA", v, status=st)
    if (st == 0) read(v, *) area_eps
    call get_environment_variable("SPHJET_SE_NOPI", v, status=st)
    no_pi = st == 0
  end subroutine read_switch

  !> Phi(g) and q = dPhi/dg: |g|^2 and 2 g (eps < 0), or sqrt(|g|^2 + eps^2) - eps and g / sqrt(..).
  pure subroutine energy_density(gx, gz, eps, ph, qx, qz)
    real(rp), intent(in) :: gx, gz, eps
    real(rp), intent(out) :: ph, qx, qz
    real(rp) :: r
    if (eps < 0.0_rp) then
      ph = gx * gx + gz * gz
      qx = 2.0_rp * gx
      qz = 2.0_rp * gz
    else
      r = sqrt(gx * gx + gz * gz + eps * eps)
      ph = r - eps
      qx = gx / r
      qz = gz / r
    end if
  end subroutine energy_density

  !> H u, H = F I + (W'' - F) e e^T the Hessian of W at the separation (dx, dz) (r^2 = r2, e its
  !> unit vector, F = (dW/dr)/r, d2 = d^2W/dr^2).
  pure elemental subroutine hessian_times(f, d2, dx, dz, r2, ux, uz, hx, hz)
    real(rp), intent(in) :: f, d2, dx, dz, r2, ux, uz
    real(rp), intent(out) :: hx, hz
    real(rp) :: eu
    eu = (d2 - f) * (dx * ux + dz * uz) / r2
    hx = f * ux + eu * dx
    hz = f * uz + eu * dz
  end subroutine hessian_times

end module surface_energy
