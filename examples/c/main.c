/*
 * symbody from C: simulate the paper's Stewart platform for one second through the C ABI
 * and print actuator 1's force, then evaluate the constraint Jacobian at the initial pose.
 *
 * Build and run with examples/c/build.sh, which also checks the force against Rust's.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "symbody.h"

/* Prints the library's message for a failed call and returns 1. */
static int fail(const char *what, int status)
{
    fprintf(stderr, "%s failed (status %d): %s\n", what, status, symbody_last_error_message());
    return 1;
}

int main(void)
{
    SymbodySession *session = NULL;
    SymbodyMechanism *mech = NULL;
    double *q0 = NULL;
    double *phi_q = NULL;
    int rc = 1;
    int status;
    double force, max_abs = 0.0;
    size_t n_coords, nnz, k;

    /* The defaults of symbody::session::Settings: HHT alpha -0.05, step 1 ms. */
    status = symbody_session_new("stewart_6_6", SYMBODY_FORMULATION_DEFAULT, -0.05, 1e-3, &session);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_session_new", status);
        goto done;
    }
    status = symbody_session_advance_to(session, 1.0);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_session_advance_to", status);
        goto done;
    }
    status = symbody_session_driver_effort(session, "act1", &force);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_session_driver_effort", status);
        goto done;
    }
    printf("leg 1 force at t = 1 s: %.15e N\n", force);

    /* The mechanism's equations directly: the constraint Jacobian at the initial pose. */
    status = symbody_mechanism_new("stewart_6_6", SYMBODY_FORMULATION_DEFAULT, &mech);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_mechanism_new", status);
        goto done;
    }
    n_coords = symbody_mechanism_n_coords(mech);
    nnz = symbody_mechanism_phi_q_nnz(mech);
    q0 = malloc(n_coords * sizeof *q0);
    phi_q = malloc(nnz * sizeof *phi_q);
    if (q0 == NULL || phi_q == NULL) {
        fprintf(stderr, "out of memory\n");
        goto done;
    }
    status = symbody_mechanism_q0(mech, q0, n_coords);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_mechanism_q0", status);
        goto done;
    }
    status = symbody_mechanism_phi_q(mech, q0, n_coords, 0.0, phi_q, nnz);
    if (status != SYMBODY_STATUS_OK) {
        rc = fail("symbody_mechanism_phi_q", status);
        goto done;
    }
    for (k = 0; k < nnz; k++) {
        if (fabs(phi_q[k]) > max_abs) {
            max_abs = fabs(phi_q[k]);
        }
    }
    printf("phi_q at q0: nnz = %zu, max |value| = %.15e\n", nnz, max_abs);
    rc = 0;

done:
    free(phi_q);
    free(q0);
    symbody_mechanism_free(mech);
    symbody_session_free(session);
    return rc;
}
