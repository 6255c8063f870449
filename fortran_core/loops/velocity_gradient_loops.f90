!> The velocity gradient of every slot, for the reconstructed artificial viscosity
!> (numerics.artificial_reconstruction; physics/viscosity.f90, reconstructed_dq). One sweep
!> over the fluid pairs that keeps them for the rates sweep after it (the same positions), then
!> per slot the kernel-gradient corrected gradient
!>   G_a = [sum_b V_b (u_b - u_a) (x) grad_a W_ab] M_a^-1,
!>   M_a = sum_b V_b (x_b - x_a) (x) grad_a W_ab,
!> which is exact for a linear velocity field whatever the neighbourhood (free surface, axis),
!> as long as M_a is invertible. V_b = m_b / rho_b with the sorted state's masses (in the
!> axisymmetric mode the planar ones, so the gradient is the meridian plane's); the mirror
!> images across the axis carry u with its sign flipped, so the gradient near the axis sees the
!> mirrored field. Like every traversal here, bitwise independent of the thread count.
module velocity_gradient_loops
  use sphjet_kinds, only: rp
  use sphjet_kernels, only: kernel_t
  use sorted_state, only: sorted_t
  use traversal, only: pair_body_t, pair_list_t, pair_sweep, PAIRS_ANY_FLUID, SWEEP_KEEP
  implicit none
  private
  public :: velocity_gradients, N_GV, G_UX, G_UZ, G_WX, G_WZ

  !> Rows of sorted_t%gv: du/dx, du/dz, dw/dx, dw/dz (x the radius in the axisymmetric
  !> mode), then the sums of M (xx, xz, zz) while the sweep runs.
  integer, parameter :: G_UX = 1, G_UZ = 2, G_WX = 3, G_WZ = 4, M_XX = 5, M_XZ = 6, M_ZZ = 7, &
                        N_GV = 7

  !> Below this determinant of M the neighbours lie near a line or are a few only: the
  !> gradient is left at 0 there, which gives the particle's pairs the plain Pi. M is the
  !> identity for a whole kernel support, diag(1/2, 1/2) (det 1/4) on a flat free surface and
  !> of det 0.04 at a right-angled corner, so surface particles are reconstructed, corners,
  !> lines and clusters of a few particles are not.
  real(rp), parameter :: DET_MIN = 0.1_rp

  type, extends(pair_body_t) :: gradient_body_t
    type(sorted_t), pointer :: s => null()
    real(rp), allocatable :: v(:)
  contains
    procedure :: visit => gradient_visit
  end type gradient_body_t

contains

  !> s%gv(G_UX:G_WZ, k) for every slot k: real fluid slots from their sums, mirror and periodic
  !> images from their particle's slot, other slots 0. Keeps the sweep's pairs (SWEEP_KEEP)
  !> for the sweeps that follow at these positions; outside an open team.
  subroutine velocity_gradients(kern, s)
    type(kernel_t), intent(in) :: kern
    type(sorted_t), intent(inout), target :: s
    type(gradient_body_t) :: body
    real(rp) :: red, det, mxx, mxz, mzz, gx, gz
    integer :: k, j, n, r
    n = s%n
    if (allocated(s%gv)) then
      if (size(s%gv, 2) < n) deallocate(s%gv)
    end if
    if (.not. allocated(s%gv)) allocate(s%gv(N_GV, max(n, 1)))
    s%gv(:, 1:n) = 0.0_rp
    body%s => s
    body%v = s%m(1:n) / s%rho(1:n)
    red = 0.0_rp
    call pair_sweep(s, kern, PAIRS_ANY_FLUID, body, red, SWEEP_KEEP)
    do k = 1, n
      if (s%src_slot(k) /= k .or. .not. s%fluid(k)) cycle
      mxx = s%gv(M_XX, k)
      mxz = s%gv(M_XZ, k)
      mzz = s%gv(M_ZZ, k)
      det = mxx * mzz - mxz * mxz
      if (det < DET_MIN) then
        s%gv(G_UX:G_WZ, k) = 0.0_rp
        cycle
      end if
      ! each row (d/dx, d/dz of u, then of w) of the sums times M^-1 = [mzz, -mxz; -mxz, mxx] / det
      do r = G_UX, G_WX, 2
        gx = s%gv(r, k)
        gz = s%gv(r + 1, k)
        s%gv(r, k) = (gx * mzz - gz * mxz) / det
        s%gv(r + 1, k) = (gz * mxx - gx * mxz) / det
      end do
    end do
    ! an image: its particle's gradient, the cross terms times the sign of its mirrored u
    ! (u'(x, z) = -u(-x, z), w'(x, z) = w(-x, z))
    do k = 1, n
      j = s%src_slot(k)
      if (j == k) cycle
      s%gv(G_UX, k) = s%gv(G_UX, j)
      s%gv(G_UZ, k) = s%usign(k) * s%gv(G_UZ, j)
      s%gv(G_WX, k) = s%usign(k) * s%gv(G_WX, j)
      s%gv(G_WZ, k) = s%gv(G_WZ, j)
    end do
  end subroutine velocity_gradients

  !> The fluid pairs of one row task: the sums of both particles. With d = x_a - x_b and
  !> grad_a W_ab = F d, pair (a, b) adds V_b (u_b - u_a) F d_j and -V_b F d_i d_j to a's sums,
  !> and the same products times V_a to b's (both signs flip for b). A particle's pairs follow
  !> each other in the list and none has it as b: its sums are carried along its run (the
  !> same additions in the same order as one pair at a time), as in rates.f90.
  subroutine gradient_visit(self, pl, red)
    class(gradient_body_t), intent(inout) :: self
    type(pair_list_t), intent(inout) :: pl
    real(rp), intent(inout) :: red
    integer :: k, a, b
    real(rp) :: fx, fz, du, dw, t(N_GV), sa(N_GV)
    associate (g => self%s%gv, u => self%s%u, w => self%s%w, v => self%v)
      k = 1
      do while (k <= pl%n)
        a = pl%a(k)
        sa = g(:, a)
        do while (k <= pl%n)
          if (pl%a(k) /= a) exit
          if (.not. pl%mixed(k)) then
            b = pl%b(k)
            fx = pl%f(k) * pl%dx(k)
            fz = pl%f(k) * pl%dz(k)
            du = u(b) - u(a)
            dw = w(b) - w(a)
            t(G_UX) = du * fx
            t(G_UZ) = du * fz
            t(G_WX) = dw * fx
            t(G_WZ) = dw * fz
            t(M_XX) = -pl%dx(k) * fx
            t(M_XZ) = -pl%dx(k) * fz
            t(M_ZZ) = -pl%dz(k) * fz
            sa = sa + v(b) * t
            g(:, b) = g(:, b) + v(a) * t
          end if
          k = k + 1
        end do
        g(:, a) = sa
      end do
    end associate
    red = max(red, 0.0_rp)
  end subroutine gradient_visit

end module velocity_gradient_loops
