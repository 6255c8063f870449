#!/usr/bin/env python3
"""The continuity operators of the axisymmetric mode on the Rayleigh-Plateau lattice
(cases/axisymmetric/README.md): the discrete div v of the linear, incompressible mode
u = I1(kr) cos kz, w = -I0(kr) sin kz (exact div v = 0) on columns 0, 1, 2, 5 of the a/dx = 10
lattice with its axis and periodic images, for three forms: the planar sum plus -rho u/r,
(1/r_a) sum mp_b (r_a v_a - r_b v_b).grad W with r = |x| for the images, and the same with
signed r (the one the core uses). Printed in units of k U I0(kr) |cos kz|. numpy only
(/usr/bin/python3). Wendland kernel, h = 1.3 dx."""
import numpy as np
a=0.01; dx=0.001; h=1.3*dx; lam=0.0897598; k=2*np.pi/lam; nz=90; dz=lam/nz
xs=(np.arange(10)+0.5)*dx; zs=(np.arange(nz)+0.5)*dz
X,Z=np.meshgrid(xs,zs,indexing='ij'); X=X.ravel(); Z=Z.ravel()
def I(n,x):
    s=0; t=(x/2)**n/__import__("math").factorial(n)
    for m in range(40): s+=t; t*= (x/2)**2/((m+1)*(m+1+n))
    return s
U=1.0
u=U*I(1,k*X)*np.cos(k*Z); w=-U*I(0,k*X)*np.sin(k*Z)
# neighbours incl. axis images and periodic images
PX=np.concatenate([X,-X]); PZ=np.concatenate([Z,Z]); PU=np.concatenate([u,-u]); PW=np.concatenate([w,w]); PR=np.concatenate([X,X])
PX=np.concatenate([PX,PX,PX]); PZ=np.concatenate([PZ,PZ+lam,PZ-lam]); PU=np.tile(PU,3); PW=np.tile(PW,3); PR=np.tile(PR,3)
A=dx*dz
def F(r):
    q=r/h; c=7/(4*np.pi*h*h)
    return np.where(q<2, c*(-5*q*(1-q/2)**3)/h/np.maximum(r,1e-30), 0.0)  # dW/dr / r for Wendland
for col in [0,1,2,5]:
    i=col*nz+10  # z index 10 (cos kz ~ .. )
    ddx=X[i]-PX; ddz=Z[i]-PZ; r=np.hypot(ddx,ddz); f=F(r); f[r<1e-12]=0
    gx=f*ddx; gz=f*ddz
    planar=np.sum(A*((u[i]-PU)*gx+(w[i]-PW)*gz))  # = -div2D v
    hoop=u[i]/X[i]
    div_planar_hoop=-planar+hoop
    ra=X[i]; rb=PR
    energy=np.sum(A*((ra*u[i]-rb*PU)*gx+(ra*w[i]-rb*PW)*gz))/ra
    signed=np.sum(A*((ra*u[i]-np.sign(PX)*rb*PU)*gx+(ra*w[i]-np.sign(PX)*rb*PW)*gz))/ra
    scale=U*k*I(0,k*X[i])*abs(np.cos(k*Z[i]))
    print(f"col {col}: exact div 0; planar+hoop {div_planar_hoop/scale:+.4f}; energy {-energy/scale:+.4f}; signed {-signed/scale:+.4f}  (units of k U I0 cos)")
