!> The axisymmetric mode's part of the rates (physics/axisymmetric.f90), on top of the planar
!> pair sweep of rates.f90 (sorted order, real slots only):
!>   continuity   drho_a/dt = (1/r_a) sum_b mp_b (r_a u_a - r_b u_b) dW_ab/dr_a
!>                            + sum_b mp_b (w_a - w_b) dW_ab/dz_a
!>                replaces the planar sum (every real particle: dynamic boundaries too); one
!>                extra sweep over the pairs with a fluid particle, images included
!>   laminar      du_r/dt += nu ((1/r) du_r/dr - u_r / r^2),  du_z/dt += nu (1/r) du_z/dr
!>                (fluid; the radial derivatives from the same sweep over the fluid pairs:
!>                du/dr|_a = sum_b A_b (u_b - u_a) dW_ab/dx_a)
!> Artificial viscosity gets no hoop term: it is numerical damping of the meridian plane,
!> not a model of a physical viscosity. Image slots (order > n_state) are left alone.
module axisymmetric_loops
  use sphjet_kinds, only: rp, VISC_LAMINAR
  use sphjet_types, only: sph_params_t
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID
  use axisymmetric, only: axis_radius, continuity_pair, viscous_hoop
  implicit none
  private
  public :: axisymmetric_rates

  !> The sweep: the continuity sum (its radial and axial parts) and, with laminar viscosity, the
  !> radial derivatives (u_b - u_a) F dx, (w_b - w_a) F dx weighted by the partner's area.
  type, extends(pair_body_t) :: axi_body_t
    type(sorted_t), pointer :: s => null()
    logical :: laminar = .false.
    real(rp), allocatable :: v(:), r(:), cont(:), dudr(:), dwdr(:)
  contains
    procedure :: visit => axi_visit
  end type axi_body_t

contains

  !> Adds the hoop terms to s%ar (and with laminar viscosity s%ax, s%az) of the real slots.
  subroutine axisymmetric_rates(prm, kern, s, n_state)
    type(sph_params_t), intent(in) :: prm
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    integer, intent(in) :: n_state
    type(axi_body_t) :: body
    integer :: k, n
    real(rp) :: red, hx, hz
    logical :: laminar

    n = s%n
    laminar = prm%viscosity == VISC_LAMINAR .and. prm%visc_value > 0.0_rp
    allocate(body%v(n), body%r(n), body%cont(n), body%dudr(n), body%dwdr(n))
    body%v = s%m(1:n) / s%rho(1:n)
    ! signed radii: an image's r is -r of its source, so that r v is smooth across the axis
    body%r = sign(axis_radius(s%x(1:n), prm%h), s%x(1:n))
    body%cont = 0.0_rp
    body%dudr = 0.0_rp
    body%dwdr = 0.0_rp
    body%laminar = laminar
    body%s => s
    red = 0.0_rp
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, red)
    !$omp parallel do schedule(static) private(hx, hz)
    do k = 1, n
      if (s%grid%order(k) > n_state) cycle
      s%ar(k) = body%cont(k) / body%r(k)
      if (laminar .and. s%fluid(k)) then
        call viscous_hoop(prm%visc_value, s%u(k), body%dudr(k), body%dwdr(k), s%x(k), prm%h, &
                          hx, hz)
        s%ax(k) = s%ax(k) + hx
        s%az(k) = s%az(k) + hz
      end if
    end do
    !$omp end parallel do
  end subroutine axisymmetric_rates

  subroutine axi_visit(self, pl, red)
    class(axi_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: k, a, b
    real(rp) :: g, du, dw, qr, qz
    associate (u => self%s%u, w => self%s%w, m => self%s%m, v => self%v, r => self%r, &
               cont => self%cont, dudr => self%dudr, dwdr => self%dwdr, fl => self%s%fluid)
      do k = 1, pl%n
        a = pl%a(k)
        b = pl%b(k)
        ! continuity: a gets mp_b (qr + r_a qz), b mp_a (qr + r_b qz) (grad_b W_ba = -grad_a W_ab and the
        ! difference changes sign too)
        call continuity_pair(r(a), u(a), w(a), r(b), u(b), w(b), pl%f(k), pl%dx(k), pl%dz(k), qr, qz)
        cont(a) = cont(a) + m(b) * (qr + r(a) * qz)
        cont(b) = cont(b) + m(a) * (qr + r(b) * qz)
        if (.not. (self%laminar .and. fl(a) .and. fl(b))) cycle
        ! dW_ab/dx_a = F dx; dW_ba/dx_b = -F dx, and u_a - u_b = -(u_b - u_a): both get + g du
        g = pl%f(k) * pl%dx(k)
        du = u(b) - u(a)
        dw = w(b) - w(a)
        dudr(a) = dudr(a) + v(b) * du * g
        dwdr(a) = dwdr(a) + v(b) * dw * g
        dudr(b) = dudr(b) + v(a) * du * g
        dwdr(b) = dwdr(b) + v(a) * dw * g
      end do
    end associate
    red = max(red, 0.0_rp)
  end subroutine axi_visit

end module axisymmetric_loops
