!> Image particles (axisymmetric mode and periodic z; sph_params_t%geometry%kind, %periodic_z):
!> which images there are (image_particles, at a list build: list_rebuild.f90), and their fields
!> between passes of a multi-pass loop (copy_to_images). gather_sorted adds, as extra sorted
!> slots, the mirror image of every active particle within 2h + skin of the axis x = 0 at the
!> build (x -> -x, u -> -u, the rest equal) and the periodic image of every particle or axis
!> image within 2h + skin of z = domain%zmin or domain%zmax at the build (z -+ lz). An image
!> slot has grid%order(k) > st%n, src(k) its source particle, usign(k) its x (and u) sign and
!> zshift(k) its z shift, fixed at the build; at every gather it is put at (usign x, z + zshift)
!> of its source's current position. The pair sums treat it as any neighbour and what
!> accumulates in its slot is discarded: every real particle sees each of its neighbours, real
!> or image, once. Pairs of two images are therefore not listed. In axisymmetric mode m holds
!> the planar mass m / (2 pi r) (physics/axisymmetric.f90), so that every pair loop is the SPH
!> of the meridian plane.
module particle_images
  use sphjet_kinds, only: rp, ip
  use sphjet_types, only: sph_params_t
  use sorted_state, only: sorted_t
  implicit none
  private
  public :: image_particles, copy_to_images

contains

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

end module particle_images
