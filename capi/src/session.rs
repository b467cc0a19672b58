//! A running simulation for C: `symbody::session::Session` behind an opaque handle (make,
//! step or advance, read the state, the multipliers, driver efforts and joint wrenches).

use crate::mechanism::{
    lookup, lookup_file, lookup_with, parameters, source, Found, SymbodyMechanism,
};
use crate::status::{arg, arg_mut, guard, guard_value, output, string, Failure, SymbodyStatus};
use std::ffi::{c_char, c_int, CString};
use symbody::session::{Session, Settings};

/// A running simulation of one mechanism (opaque): HHT-α from a consistent start at t = 0.
/// Made by `symbody_session_new` (or `_new_ex`, `_from_file`), released by
/// `symbody_session_free`. A handle may be moved between threads but used by one at a time;
/// distinct handles are independent.
pub struct SymbodySession {
    session: Session,
    /// The file the equations are interpreted from; `None` for compiled code.
    source: Option<CString>,
}

/// Builds a session of the registered mechanism `name` in `formulation` (a
/// `SymbodyFormulation`) with HHT parameter `alpha` in [-1/3, 0] and step `step` (s)
/// (the paper's: -0.05 and 1e-3), started consistently at t = 0 from the mechanism file's
/// pose and velocities, and stores it in `*out` (NULL on failure). Release it with
/// `symbody_session_free`. The same as `symbody_session_new_ex` with no flags.
///
/// `name` may also be the path of a mechanism file (ending in `.toml` or with a folder): it
/// runs interpreted, as with `symbody_mechanism_new`; `symbody_session_from_file` takes any
/// path.
///
/// Errors: `SYMBODY_STATUS_UNKNOWN_NAME` (the message lists the registered names),
/// `SYMBODY_STATUS_INVALID_ARGUMENT` (formulation, alpha, step), `SYMBODY_STATUS_SOLVER`
/// (no consistent start), and for a file `SYMBODY_STATUS_FILE_NOT_FOUND` and
/// `SYMBODY_STATUS_INVALID_FILE` (see `symbody_mechanism_from_file`).
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `out` is NULL or points to writable storage
/// for one pointer.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_new(
    name: *const c_char,
    formulation: c_int,
    alpha: f64,
    step: f64,
    out: *mut *mut SymbodySession,
) -> c_int {
    // SAFETY: the same contract.
    unsafe { symbody_session_new_ex(name, formulation, alpha, step, 0, out) }
}

/// Flag of `symbody_session_new_ex`: pass singular positions (a linkage lying flat), where
/// constraint rows are dependent for an instant; the steps and the multipliers drop those
/// rows (their joints carry no load at such a state) instead of failing.
pub const SYMBODY_CROSS_SINGULAR_POSITIONS: u32 = 1;
/// Flag of `symbody_session_new_ex`: project the velocities onto the constraints after
/// every step.
pub const SYMBODY_PROJECT_VELOCITIES: u32 = 2;

/// As `symbody_session_new`, with `flags`: a bitwise or of `SYMBODY_CROSS_SINGULAR_POSITIONS`
/// and `SYMBODY_PROJECT_VELOCITIES` (0 for none). Unknown bits are
/// `SYMBODY_STATUS_INVALID_ARGUMENT`.
///
/// # Safety
/// As `symbody_session_new`.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_new_ex(
    name: *const c_char,
    formulation: c_int,
    alpha: f64,
    step: f64,
    flags: u32,
    out: *mut *mut SymbodySession,
) -> c_int {
    // SAFETY: the same contract.
    unsafe {
        new_session(
            name,
            "name",
            formulation,
            (alpha, step, None),
            flags,
            out,
            &lookup,
        )
    }
}

/// As `symbody_session_new_ex`, with step-size control instead of the fixed step: every
/// step's local error estimate in positions and velocities is kept within `rtol` (relative)
/// and `atol` (absolute), `step` is the first step tried, and every time asked of
/// `symbody_session_advance_to` is landed on exactly. Velocities are projected after every
/// step (the control needs it), whatever the flags say.
///
/// Errors: those of `symbody_session_new_ex`, and `SYMBODY_STATUS_INVALID_ARGUMENT` for a
/// tolerance that is not positive and finite.
///
/// # Safety
/// As `symbody_session_new`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn symbody_session_new_controlled(
    name: *const c_char,
    formulation: c_int,
    alpha: f64,
    step: f64,
    rtol: f64,
    atol: f64,
    flags: u32,
    out: *mut *mut SymbodySession,
) -> c_int {
    // SAFETY: the same contract.
    unsafe {
        new_session(
            name,
            "name",
            formulation,
            (alpha, step, Some((rtol, atol))),
            flags,
            out,
            &lookup,
        )
    }
}

/// As `symbody_session_new_ex` for the mechanism file at `path`, always a path whatever its
/// name (see `symbody_mechanism_from_file`): its equations run interpreted, nothing compiled.
///
/// Errors: those of `symbody_session_new_ex`, with `SYMBODY_STATUS_FILE_NOT_FOUND` and
/// `SYMBODY_STATUS_INVALID_FILE` for the file.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string; `out` is NULL or points to writable storage
/// for one pointer.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_from_file(
    path: *const c_char,
    formulation: c_int,
    alpha: f64,
    step: f64,
    flags: u32,
    out: *mut *mut SymbodySession,
) -> c_int {
    // SAFETY: the same contract.
    unsafe {
        new_session(
            path,
            "path",
            formulation,
            (alpha, step, None),
            flags,
            out,
            &lookup_file,
        )
    }
}

/// As `symbody_session_new_ex`, with parameters of the mechanism's file set before the
/// session starts: `names[i]` to `values[i]` for `i < count`, as
/// `symbody_mechanism_with_parameters` does (the file loaded at these values). Errors: those of `symbody_session_new_ex` and of
/// `symbody_mechanism_with_parameters`.
///
/// # Safety
/// As `symbody_session_new`; when `count > 0`, `names` and `values` point to `count`
/// readable entries and each name is a NUL-terminated string.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn symbody_session_with_parameters(
    name: *const c_char,
    formulation: c_int,
    alpha: f64,
    step: f64,
    flags: u32,
    names: *const *const c_char,
    values: *const f64,
    count: usize,
    out: *mut *mut SymbodySession,
) -> c_int {
    let find = |what: &str, f: c_int| {
        // SAFETY: the caller's contract.
        let params = unsafe { parameters(names, values, count)? };
        lookup_with(what, f, &params)
    };
    // SAFETY: the same contract.
    unsafe {
        new_session(
            name,
            "name",
            formulation,
            (alpha, step, None),
            flags,
            out,
            &find,
        )
    }
}

/// Builds a session of what `what` names, resolved by `find`.
///
/// # Safety
/// As for `symbody_session_new`.
#[allow(clippy::too_many_arguments)]
unsafe fn new_session(
    what: *const c_char,
    arg_name: &str,
    formulation: c_int,
    (alpha, step, tolerances): (f64, f64, Option<(f64, f64)>),
    flags: u32,
    out: *mut *mut SymbodySession,
    find: &dyn Fn(&str, c_int) -> Found,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above.
        let out = unsafe { arg_mut(out, "out")? };
        *out = std::ptr::null_mut();
        // SAFETY: the caller's contract above.
        let what = unsafe { string(what, arg_name)? };
        let known = SYMBODY_CROSS_SINGULAR_POSITIONS | SYMBODY_PROJECT_VELOCITIES;
        if flags & !known != 0 {
            return Err(Failure::new(
                SymbodyStatus::InvalidArgument,
                format!("flags: unknown bits {:#x}; the flags are SYMBODY_CROSS_SINGULAR_POSITIONS (1) and SYMBODY_PROJECT_VELOCITIES (2)", flags & !known),
            ));
        }
        if let Some((rtol, atol)) = tolerances {
            symbody::generic::tolerances(Some(rtol), Some(atol), "")
                .map_err(|m| Failure::new(SymbodyStatus::InvalidArgument, m))?;
        }
        // Resolves the name or file and the formulation with this API's statuses.
        let (entry, mech) = find(what, formulation)?;
        let settings = Settings {
            formulation: Some(mech.info().formulation),
            alpha,
            step,
            cross_singular_positions: flags & SYMBODY_CROSS_SINGULAR_POSITIONS != 0,
            project_velocities: flags & SYMBODY_PROJECT_VELOCITIES != 0,
            tolerances,
        };
        let session = Session::with_mechanism(mech, settings)
            .map_err(|e| Failure::from_session(e, SymbodyStatus::InvalidArgument))?;
        *out = Box::into_raw(Box::new(SymbodySession {
            session,
            source: source(entry),
        }));
        Ok(())
    })
}

/// Releases a session; NULL is ignored.
///
/// # Safety
/// `s` is NULL or a handle from this library not yet freed; it is not used afterwards.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_free(s: *mut SymbodySession) {
    guard_value((), || {
        if !s.is_null() {
            // SAFETY: made by Box::into_raw and, by the caller's contract, not yet freed.
            drop(unsafe { Box::from_raw(s) });
        }
        Ok(())
    })
}

/// Stores a new handle to the session's mechanism (its formulation) in `*out` (NULL on
/// failure), for its sizes, names and equations. Release it with `symbody_mechanism_free`;
/// it stays valid after the session is freed.
///
/// # Safety
/// `s` is NULL or a live handle; `out` is NULL or points to writable storage for one
/// pointer.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_mechanism(
    s: *const SymbodySession,
    out: *mut *mut SymbodyMechanism,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above.
        let out = unsafe { arg_mut(out, "out")? };
        *out = std::ptr::null_mut();
        // SAFETY: the caller's contract above.
        let s = unsafe { arg(s, "session")? };
        *out = Box::into_raw(Box::new(SymbodyMechanism::new(
            s.session.mechanism(),
            s.source.clone(),
        )));
        Ok(())
    })
}

/// The session's time (s); NaN (with an error message) if `s` is NULL.
///
/// # Safety
/// `s` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_t(s: *const SymbodySession) -> f64 {
    guard_value(f64::NAN, || {
        // SAFETY: the caller's contract above.
        Ok(unsafe { arg(s, "session")? }.session.t())
    })
}

/// The session behind `s`.
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during `'a`.
unsafe fn session<'a>(s: *mut SymbodySession) -> Result<&'a mut Session, Failure> {
    // SAFETY: the caller's contract.
    Ok(&mut unsafe { arg_mut(s, "session")? }.session)
}

fn solver(e: symbody::session::Error) -> Failure {
    Failure::from_session(e, SymbodyStatus::InvalidArgument)
}

/// Takes one HHT step of the nominal size (cut internally on failure).
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_step(s: *mut SymbodySession) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        unsafe { session(s)? }.step().map_err(solver)
    })
}

/// Steps until exactly time `t` (s), the last step shortened to land on it. `t` must be
/// finite and not before the session's time (`SYMBODY_STATUS_INVALID_ARGUMENT`).
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_advance_to(s: *mut SymbodySession, t: f64) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        unsafe { session(s)? }.advance_to(t).map_err(solver)
    })
}

/// Copies the coordinates q into `buf`, which holds `len >= symbody_mechanism_n_coords`
/// entries.
///
/// # Safety
/// `s` is NULL or a live handle; `buf` is NULL or points to `len` writable doubles.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_q(
    s: *const SymbodySession,
    buf: *mut f64,
    len: usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above; length checked inside.
        let q = unsafe { arg(s, "session")? }.session.q();
        unsafe { output(buf, len, q.len(), "buf")? }.copy_from_slice(q);
        Ok(())
    })
}

/// Copies the velocities q̇ into `buf`, which holds `len >= symbody_mechanism_n_coords`
/// entries.
///
/// # Safety
/// `s` is NULL or a live handle; `buf` is NULL or points to `len` writable doubles.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_qd(
    s: *const SymbodySession,
    buf: *mut f64,
    len: usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above; length checked inside.
        let qd = unsafe { arg(s, "session")? }.session.qd();
        unsafe { output(buf, len, qd.len(), "buf")? }.copy_from_slice(qd);
        Ok(())
    })
}

/// Copies the Lagrange multipliers λ of the current state (one per constraint row, from
/// `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]`) into `buf`, which holds
/// `len >= symbody_mechanism_n_constraints` entries. Redundant rows have λ = 0.
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call; `buf` is NULL or
/// points to `len` writable doubles.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_multipliers(
    s: *mut SymbodySession,
    buf: *mut f64,
    len: usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let s = unsafe { session(s)? };
        let lambda = s.multipliers().map_err(solver)?;
        // SAFETY: the caller's contract; length checked inside.
        unsafe { output(buf, len, lambda.len(), "buf")? }.copy_from_slice(lambda);
        Ok(())
    })
}

/// Writes the effort of every driver (force in N or torque in N·m on the driven body,
/// positive along increasing driven coordinate) into `buf`, in driver order
/// (`symbody_mechanism_driver_name`), and the number of drivers into `*n_written`. If
/// `len` is shorter than that, nothing is written to `buf`, `*n_written` still receives
/// the number needed, and the status is `SYMBODY_STATUS_BUFFER_TOO_SHORT`.
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call; `buf` is NULL or
/// points to `len` writable doubles; `n_written` is NULL or points to a writable `size_t`.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_driver_efforts(
    s: *mut SymbodySession,
    buf: *mut f64,
    len: usize,
    n_written: *mut usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let s = unsafe { session(s)? };
        // SAFETY: the caller's contract.
        let n_written = unsafe { arg_mut(n_written, "n_written")? };
        *n_written = 0;
        let need = s.driver_efforts(&mut []).map_err(solver)?;
        *n_written = need;
        // SAFETY: the caller's contract; length checked inside.
        let buf = unsafe { output(buf, len, need, "buf")? };
        s.driver_efforts(buf).map_err(solver)?;
        Ok(())
    })
}

/// Stores the effort of the driver called `name` (see `symbody_session_driver_efforts`) in
/// `*out`. Errors: `SYMBODY_STATUS_UNKNOWN_NAME` (the message lists the joints),
/// `SYMBODY_STATUS_INVALID_ARGUMENT` if the joint is not a driver.
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call; `name` is NULL or
/// a NUL-terminated string; `out` is NULL or points to a writable double.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_driver_effort(
    s: *mut SymbodySession,
    name: *const c_char,
    out: *mut f64,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let s = unsafe { session(s)? };
        // SAFETY (both): the caller's contract.
        let name = unsafe { string(name, "name")? };
        let out = unsafe { arg_mut(out, "out")? };
        *out = s
            .driver_effort(name)
            .map_err(|e| Failure::from_session(e, SymbodyStatus::UnknownName))?;
        Ok(())
    })
}

/// Writes the wrench the joint (or driver) called `name` exerts on its first body, in the
/// global frame: `force` (N, 3 entries) and `moment` about the joint point (N·m, 3
/// entries). Errors: `SYMBODY_STATUS_UNKNOWN_NAME` (the message lists the joints),
/// `SYMBODY_STATUS_INVALID_ARGUMENT` when the reaction is not recoverable there.
///
/// # Safety
/// `s` is NULL or a live handle used by no other thread during the call; `name` is NULL or
/// a NUL-terminated string; `force` and `moment` are NULL or point to 3 writable doubles
/// each.
#[no_mangle]
pub unsafe extern "C" fn symbody_session_joint_wrench(
    s: *mut SymbodySession,
    name: *const c_char,
    force: *mut f64,
    moment: *mut f64,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let s = unsafe { session(s)? };
        // SAFETY (all three): the caller's contract.
        let name = unsafe { string(name, "name")? };
        let force = unsafe { output(force, 3, 3, "force")? };
        let moment = unsafe { output(moment, 3, 3, "moment")? };
        let w = s
            .joint_wrench(name)
            .map_err(|e| Failure::from_session(e, SymbodyStatus::UnknownName))?;
        force.copy_from_slice(&w.force);
        moment.copy_from_slice(&w.moment);
        Ok(())
    })
}
