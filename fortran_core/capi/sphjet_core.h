/* The C interface of the sphjet Fortran core (fortran_core/capi/sphjet_capi.f90).
 * Kept in step with the Fortran by tests/interface (gfortran -fc-prototypes).
 * All arrays are owned by the caller; the core never frees them. Every function that can
 * fail returns an SPH_* status; none of them stops the program. */
#ifndef SPHJET_CORE_H
#define SPHJET_CORE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    SPH_OK = 0,
    SPH_ERR_ARGUMENT = 1,      /* bad count, null pointer, unsupported option */
    SPH_ERR_NONFINITE = 2,     /* NaN or Inf in a field */
    SPH_ERR_DENSITY = 3,       /* density outside [rho_min, rho_max] */
    SPH_ERR_OUT_OF_DOMAIN = 4, /* a particle left the domain (removal off) */
    SPH_ERR_DT_COLLAPSE = 5,   /* time step below dt_min */
    SPH_ERR_CAPACITY = 6       /* output buffer too small */
};

/* The scalar parameters of a run, one struct per concern (sphjet_types.f90 mirrors each).
 * A new parameter goes into the struct of its concern, in the same place on both sides:
 * kernel, smoothing and SPH corrections in numerics; the step control in time_step; the
 * equation of state in eos; the domain box and the density band in domain; the fluid's
 * viscosity in viscosity; the wall model, its viscous term and the gate in boundary; CSF in
 * surface_tension; the driven nozzle in nozzle; planar/axisymmetric and periodicity in
 * geometry; body forces in gravity. A concern with none of these gets its own struct. */
typedef struct sph_numerics_t {
    int kernel;               /* 1 Gaussian, 2 quadratic, 3 cubic spline, 4 its Thomas-Couchman gradient, 5 Wendland */
    int density_filter;       /* 0 none, 1 Shepard, 2 MLS */
    int tensile;              /* 1: tensile-instability correction on */
    int integrator;           /* 1 predictor-corrector, 2 leapfrog (fluid particles alone) */
    double h;                 /* smoothing length [m] */
    double xsph_eps;          /* XSPH epsilon */
    double density_diffusion; /* delta of the density diffusion (delta-SPH); 0 = off */
    double bulk_viscosity;    /* beta of the bulk viscosity zeta = beta rho0 c0 h; 0 = off */
    double shifting;          /* A of the shifting velocity -A h (c0/10) grad C; 0 = off */
} sph_numerics_t;

typedef struct sph_time_step_t {
    int variable_dt;          /* 1: dt from the CFL condition each step */
    double cfl;               /* Courant number */
    double dt_min;            /* a step below this is a collapse [s] */
    double dt_max;            /* the variable step's cap [s]; 0: none */
} sph_time_step_t;

typedef struct sph_eos_t {    /* Tait equation of state */
    double rho0;              /* reference density [kg/m^3] */
    double b;                 /* Tait B [Pa] */
    double gamma;             /* Tait exponent */
    double c0;                /* sound speed at rho0 [m/s] */
} sph_eos_t;

typedef struct sph_domain_t {
    int remove_out;           /* 1: remove leavers and count them; 0: fail */
    double xmin;              /* fluid beyond these bounds leaves the domain [m] */
    double xmax;
    double zmin;
    double zmax;
    double rho_min;           /* sane density band [kg/m^3]; rho_max <= 0 disables */
    double rho_max;
} sph_domain_t;

typedef struct sph_viscosity_t {
    int model;                /* 1 artificial, 2 laminar */
    double value;             /* alpha (artificial) or nu [m^2/s] (laminar) */
    double artificial_alpha;  /* laminar: an artificial alpha on top; 0 = off */
    int reconstruct;          /* 1: Pi of the velocity jump left after the linear
                                 reconstruction to the pair's midpoint */
} sph_viscosity_t;

typedef struct sph_boundary_t {
    int model;                /* 1 repulsive (Monaghan-Kos), 2 dynamic */
    int dbc_period;           /* steps between dynamic-boundary density updates */
    double coef;              /* speed-of-sound coefficient (repulsive walls) */
    double h_swl;             /* still-water depth [m] (repulsive walls) */
    double viscosity;         /* nu of the repulsive-wall viscous term [m^2/s] */
    double gate_vx;           /* moving boundary (gate) velocity from gate_t_start [m/s] */
    double gate_vz;
    double gate_t_start;      /* time the gate starts moving [s] */
    double gate_z_cap;        /* a gate particle rises no higher [m] */
} sph_boundary_t;

typedef struct sph_surface_tension_t {
    int delta;                /* CSF delta in eq 24: 0 pressure-consistent (free surface), 1 colour gradient (paper) */
    int rings_curvature;      /* rings pair's surface rows: 0 neighbours' mean, 1 own */
    int curvature_normals;    /* free-surface curvature's normals: 0 all, 1 within h of the surface */
    int curvature;            /* free-surface curvature: 0 the normals' divergence, 1 surface fit */
    int free_bodies;          /* 1: each free body's net surface-tension force removed (surface_tension_loops.f90) */
    int thin_rings;           /* 1: free rings thinner than the kernel take the normals' curvature (free_body_loops.f90) */
    int fit_points_min;       /* the fewest points a surface fit may pass through, >= 0; 0-3 the three a parabola needs */
    double sigma;             /* surface tension [N/m]; 0 = off */
} sph_surface_tension_t;

typedef struct sph_nozzle_t {
    double u;                 /* driven nozzle: plug speed along the axis [m/s]; 0 = no nozzle */
    double x0;                /* orifice centre [m] */
    double z0;
    double ex;                /* unit jet axis (flow direction) */
    double ez;
    double half_width;        /* plug half-width across the axis [m] */
    double profile_a;         /* parabolic exit profile's wall distance [m]; 0 = rigid plug */
    double profile_k;         /* its centre speed / u (the lattice's flux equals u's) */
    double profile_lmax;      /* the outer line's distance: farther fluid moves with it [m] */
    double profile_rho;       /* the density a profiled plug holds [kg/m^3] */
    int release;              /* 1: a plug particle turns free at its crossing of the orifice line;
                                 2: that, and each step is shortened so that the plug's rows cross the
                                 line at a step's end (nozzle_drive.f90, landed_step; info->dt out) */
} sph_nozzle_t;

typedef struct sph_geometry_t {
    int kind;                 /* 0 planar (x, z); 1 axisymmetric (x = r >= 0, symmetry axis x = 0) */
    int periodic_z;           /* 1: periodic in z with period domain.zmax - domain.zmin */
    int axis_pair;            /* axisymmetric pair: 0 smoothed radius, 1 rings */
    double axis_m1;           /* rings pair: a ring lighter is in the first column [kg] */
    double ring_mass_per_radius; /* domain.split_axis_rings: 2 pi rho0 dx dz [kg/m]; 0 = off */
    int renormalise_continuity;  /* rings pair: 1 its continuity renormalised along r and z */
    double renormalise_reach;    /* > 0: renormalised only nearer the nozzle's orifice than this along
                                    its axis [m] (a jet's intact length), faded over the last 2h; <= 0: everywhere */
    int bound_xsph;              /* rings pair: 1 each ring's XSPH correction divided by its planar kernel
                                    sum where that exceeds 1 (axisymmetric_loops.f90) */
} sph_geometry_t;

typedef struct sph_gravity_t {
    double gx;                /* gravity [m/s^2] */
    double gz;
} sph_gravity_t;

typedef struct sph_params_t {
    sph_numerics_t numerics;
    sph_time_step_t time_step;
    sph_eos_t eos;
    sph_domain_t domain;
    sph_viscosity_t viscosity;
    sph_boundary_t boundary;
    sph_surface_tension_t surface_tension;
    sph_nozzle_t nozzle;
    sph_geometry_t geometry;
    sph_gravity_t gravity;
} sph_params_t;

typedef struct sph_arrays_t {
    int64_t n;                /* particles */
    int64_t nb;               /* boundary particles (they come first) */
    double* x;                /* position [m] */
    double* z;
    double* u;                /* velocity [m/s] */
    double* w;
    double* rho;              /* density [kg/m^3] */
    double* p;                /* pressure [Pa] */
    double* c;                /* sound speed [m/s] */
    double* m;                /* mass [kg] */
    int* kind;                /* 0 fixed boundary, 1 moving boundary, 2 fluid */
    int* active;              /* 1 in the domain, 0 removed */
    double* xo;               /* integrator work space: start-of-step values */
    double* zo;
    double* uo;
    double* wo;
    double* rhoo;
    double* ax;               /* pair accelerations (gravity excluded) [m/s^2] */
    double* az;
    double* ar;               /* density rate [kg/m^3/s] */
    double* xsph_u;           /* XSPH velocity correction [m/s] */
    double* xsph_w;
    int* wall_prev;           /* repulsive walls: neighbours along the wall (0-based) */
    int* wall_next;
    double* wall_nx;          /* wall unit normal (set by sph_prepare) */
    double* wall_nz;
    double* wall_dback;       /* spacing to the previous / next wall particle [m] */
    double* wall_dfwd;
    double* colour;           /* surface tension fields (may be NULL when sigma = 0) */
    double* st_nx;
    double* st_nz;
    double* kappa;
    double* list_x;           /* positions at the last neighbour-list build (may be NULL; */
    double* list_z;           /* NaN = none yet); a checkpoint keeps them [m] */
} sph_arrays_t;

typedef struct sph_step_info_t {
    double dt;                /* in: step to take [s] */
    double time;              /* in: time at the start of the step [s] */
    double dt_next;           /* out: step for the next call [s] */
    double dt_f;              /* out: force and CFL time-step terms of the corrector [s] */
    double dt_cv;
    double dt_new;
    double visc_dt;           /* out: max (u_ab . r_ab)/(r^2 + eta^2) [1/s] */
    int64_t dbc_counter;      /* in/out: steps since the last boundary density update */
    int64_t n_removed;        /* out: particles removed in this step */
    int64_t bad_particle;     /* out: 0-based index of the offending particle, -1 if none */
    int bad_cause;            /* out: status of the failure */
    int rates_kept;           /* in/out (leapfrog): 1 when ax, az, ar and the XSPH correction
                                 are the rates of the state as it is */
} sph_step_info_t;

void* sph_workspace_create(void);
void sph_workspace_destroy(void* handle);
void sph_set_threads(int n);
int sph_get_threads(void);
/* The threads a step or filter call of n particles runs on: the count set, at most one per
   PARTICLES_PER_THREAD (sphjet_capi.f90) particles, at least one. */
int sph_threads_for(int n);
int sph_prepare(const sph_params_t* prm, const sph_arrays_t* arr);
int sph_step(void* ws_handle, const sph_params_t* prm, const sph_arrays_t* arr,
             sph_step_info_t* info);
int sph_density_filter(void* ws_handle, const sph_params_t* prm, const sph_arrays_t* arr,
                       int64_t* n_singular);
int sph_check_state(const sph_params_t* prm, const sph_arrays_t* arr, int64_t* bad_particle);
/* domain.split_axis_rings: the 0-based indices of the active fluid rings heavier than the
 * split limit (physics/axisymmetric.f90, ring_too_heavy), at most capacity of them, in idx;
 * their number in n_found (it may exceed capacity: call again with more room). */
int sph_axis_rings_to_split(const sph_params_t* prm, const sph_arrays_t* arr, int64_t capacity, int64_t* idx,
                            int64_t* n_found);
int sph_compute_rates(void* ws_handle, const sph_params_t* prm, const sph_arrays_t* arr,
                      double* visc_max);
int sph_kernel_eval(int kernel, double h, int64_t n, const double* r, double* w, double* f);
/* The surface fit's parabola through n points (px, pz), weights om, seen from a particle at the
   origin with unit normal (nx, nz) and spacing sqrt(V) (surface_tension.curvature =
   "surface_fit"): its in-plane curvature, the radial part of its normal and its point's offset
   along the normal; fitted = 0 where the fit is refused (fewer than three distinct points along
   the tangent, or a radius of curvature below one spacing), the outputs then 0. */
int sph_surface_fit(int64_t n, const double* px, const double* pz, const double* om, double nx,
                    double nz, double spacing, int points_min, double* kin, double* nrx, double* c0,
                    int* fitted);
int sph_neighbour_pairs(const sph_params_t* prm, const sph_arrays_t* arr, int64_t capacity,
                        int64_t* pi_, int64_t* pj_, int64_t* npairs);
int sph_eos(const sph_params_t* prm, int64_t n, const double* rho, double* p, double* c);
/* CSF fields of the current state without stepping: colour, normal (unnormalised colour
 * gradient) and curvature into arr->colour, st_nx, st_nz, kappa (all four required); when
 * arr->ax and arr->az are given, the surface-tension acceleration alone (paper eq 24) there. */
int sph_surface_tension_fields(void* ws_handle, const sph_params_t* prm,
                               const sph_arrays_t* arr);

#ifdef __cplusplus
}
#endif

#endif /* SPHJET_CORE_H */
