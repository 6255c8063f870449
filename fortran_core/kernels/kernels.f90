!> Kernel selection: the case picks one kernel; its constants are set up once (kernel_t) and
!> the pair loops call kernel_eval, which returns W and F = (dW/dr)/r so that
!> grad_a W_ab = F (r_a - r_b).
module sphjet_kernels
  use sphjet_kinds, only: rp, ip, KERNEL_GAUSSIAN, KERNEL_QUADRATIC, KERNEL_CUBIC, KERNEL_CUBIC_TC, &
                          KERNEL_WENDLAND
  use kernel_wendland, only: wendland_norm, wendland_f, wendland_dfdq_q
  use kernel_cubic, only: cubic_norm, cubic_f, cubic_dfdq, cubic_tc_dfdq
  use kernel_quadratic, only: quadratic_norm, quadratic_f, quadratic_dfdq
  use kernel_gaussian, only: gaussian_norm, gaussian_f, gaussian_dfdq
  implicit none
  private
  public :: kernel_t, kernel_setup, kernel_eval, kernel_eval_list, kernel_w0, kernel_valid, &
            kernel_profile

  type :: kernel_t
    integer(ip) :: kind = KERNEL_WENDLAND
    real(rp) :: h = 1.0_rp, inv_h = 1.0_rp
    real(rp) :: aw = 0.0_rp   !< norm / h^2
    real(rp) :: adw = 0.0_rp  !< norm / h^3
    real(rp) :: adq = 0.0_rp  !< norm / h^4 (F of a kernel whose df/dq has a factor q)
    real(rp) :: support2 = 4.0_rp  !< (2h)^2
  end type kernel_t

contains

  pure logical function kernel_valid(kind)
    integer(ip), intent(in) :: kind
    kernel_valid = any(kind == [KERNEL_GAUSSIAN, KERNEL_QUADRATIC, KERNEL_CUBIC, KERNEL_CUBIC_TC, &
                                KERNEL_WENDLAND])
  end function kernel_valid

  pure function kernel_setup(kind, h) result(k)
    integer(ip), intent(in) :: kind
    real(rp), intent(in) :: h
    type(kernel_t) :: k
    real(rp) :: norm
    select case (kind)
    case (KERNEL_GAUSSIAN);  norm = gaussian_norm
    case (KERNEL_QUADRATIC); norm = quadratic_norm
    case (KERNEL_CUBIC, KERNEL_CUBIC_TC); norm = cubic_norm
    case default;            norm = wendland_norm
    end select
    k%kind = kind
    k%h = h
    k%inv_h = 1.0_rp / h
    k%aw = norm / (h * h)
    k%adw = norm / (h * h * h)
    k%adq = norm / (h * h * h * h)
    k%support2 = 4.0_rp * h * h
  end function kernel_setup

  !> W and F = (dW/dr)/r at distance r > 0 (r < 2h assumed by callers; 0 beyond).
  pure subroutine kernel_eval(k, r, w, f)
    type(kernel_t), intent(in) :: k
    real(rp), intent(in) :: r
    real(rp), intent(out) :: w, f
    real(rp) :: q
    q = r * k%inv_h
    select case (k%kind)
    case (KERNEL_WENDLAND)
      w = k%aw * wendland_f(q);  f = k%adq * wendland_dfdq_q(q)
    case (KERNEL_CUBIC)
      w = k%aw * cubic_f(q);     f = k%adw * cubic_dfdq(q) / r
    case (KERNEL_CUBIC_TC)
      w = k%aw * cubic_f(q);     f = k%adw * cubic_tc_dfdq(q) / r
    case (KERNEL_QUADRATIC)
      w = k%aw * quadratic_f(q); f = k%adw * quadratic_dfdq(q) / r
    case default
      w = k%aw * gaussian_f(q);  f = k%adw * gaussian_dfdq(q) / r
    end select
  end subroutine kernel_eval

  !> W and F of a list of squared distances 0 < r2 < (2h)^2, the kernel chosen once outside
  !> the loop so that each branch is a plain vectorisable loop. Same arithmetic as kernel_eval.
  pure subroutine kernel_eval_list(k, r2, w, f)
    type(kernel_t), intent(in) :: k
    real(rp), intent(in) :: r2(:)
    real(rp), intent(out) :: w(:), f(:)
    integer :: i
    real(rp) :: r, q
    ! one loop per kernel, W and F of a pair together (one pass over the list, not four).
    ! Each loop names its kernel's functions so that the compiler inlines and vectorises them:
    ! one loop calling kernel_eval (the choice inside) was 11% slower on Case1 (Wendland) and
    ! 12% on the obstacle case with the cubic spline (measured at 4005352)
    select case (k%kind)
    case (KERNEL_WENDLAND)
      do i = 1, size(r2)
        q = sqrt(r2(i)) * k%inv_h   ! Wendland's F needs no division by r
        w(i) = k%aw * wendland_f(q)
        f(i) = k%adq * wendland_dfdq_q(q)
      end do
    case (KERNEL_CUBIC)
      do i = 1, size(r2)
        r = sqrt(r2(i))
        q = r * k%inv_h
        w(i) = k%aw * cubic_f(q)
        f(i) = k%adw * cubic_dfdq(q) / r
      end do
    case (KERNEL_CUBIC_TC)
      do i = 1, size(r2)
        r = sqrt(r2(i))
        q = r * k%inv_h
        w(i) = k%aw * cubic_f(q)
        f(i) = k%adw * cubic_tc_dfdq(q) / r
      end do
    case (KERNEL_QUADRATIC)
      do i = 1, size(r2)
        r = sqrt(r2(i))
        q = r * k%inv_h
        w(i) = k%aw * quadratic_f(q)
        f(i) = k%adw * quadratic_dfdq(q) / r
      end do
    case default
      do i = 1, size(r2)
        r = sqrt(r2(i))
        q = r * k%inv_h
        w(i) = k%aw * gaussian_f(q)
        f(i) = k%adw * gaussian_dfdq(q) / r
      end do
    end select
  end subroutine kernel_eval_list

  !> W(0), the self contribution of summation formulas.
  pure function kernel_w0(k) result(w0)
    type(kernel_t), intent(in) :: k
    real(rp) :: w0
    select case (k%kind)
    case (KERNEL_WENDLAND);  w0 = k%aw * wendland_f(0.0_rp)
    case (KERNEL_CUBIC, KERNEL_CUBIC_TC); w0 = k%aw * cubic_f(0.0_rp)
    case (KERNEL_QUADRATIC); w0 = k%aw * quadratic_f(0.0_rp)
    case default;            w0 = k%aw * gaussian_f(0.0_rp)
    end select
  end function kernel_w0

  !> The kernel's profile across a line at distance y from the centre, P(y) = int W(s, y) ds
  !> over s in (-2h, 2h): midpoint sums of nq cells over s in (0, 2h), doubled [1/m].
  pure function kernel_profile(k, y, nq) result(p)
    type(kernel_t), intent(in) :: k
    real(rp), intent(in) :: y
    integer, intent(in) :: nq
    real(rp) :: p, cell, s, r, w, f, acc
    integer :: i
    cell = 2.0_rp * k%h / nq
    acc = 0.0_rp
    do i = 1, nq
      s = (i - 0.5_rp) * cell
      r = sqrt(s * s + y * y)
      if (r * r < k%support2) then
        call kernel_eval(k, r, w, f)
        acc = acc + w
      end if
    end do
    p = 2.0_rp * acc * cell
  end function kernel_profile

end module sphjet_kernels
