//! The C ABI called as C calls it (raw pointers, lengths, statuses), from Rust: the session's
//! numbers are the Rust session's bit for bit, the mechanism functions are the generated
//! code's, and every misuse (unknown names, null pointers, short buffers, bad settings) is a
//! status with a message, never a panic or a crash.

use std::ffi::{c_char, c_int, CStr, CString};
use std::ptr::{null, null_mut};
use symbody::session::{paper_leg1_force_at_1s, Session, Settings};
use symbody_c::*;

const OK: c_int = SymbodyStatus::Ok as c_int;

fn status(s: SymbodyStatus) -> c_int {
    s as c_int
}

fn last_error() -> String {
    // SAFETY: the library's NUL-terminated message, read before the next call.
    unsafe { CStr::from_ptr(symbody_last_error_message()) }
        .to_str()
        .expect("UTF-8 message")
        .to_string()
}

fn cstr(s: &str) -> CString {
    CString::new(s).unwrap()
}

/// A session of the paper scenario (the defaults of `Settings`).
fn paper_session() -> *mut SymbodySession {
    let mut s = null_mut();
    let name = cstr("stewart_6_6");
    let d = Settings::default();
    // SAFETY: valid string and out pointer.
    let rc = unsafe { symbody_session_new(name.as_ptr(), 0, d.alpha, d.step, &mut s) };
    assert_eq!(rc, OK, "{}", last_error());
    assert!(!s.is_null());
    s
}

fn mechanism(name: &str, formulation: c_int) -> Result<*mut SymbodyMechanism, (c_int, String)> {
    let mut m = null_mut();
    let name = cstr(name);
    // SAFETY: valid string and out pointer.
    match unsafe { symbody_mechanism_new(name.as_ptr(), formulation, &mut m) } {
        OK => Ok(m),
        rc => {
            assert!(m.is_null(), "a failed call leaves *out NULL");
            Err((rc, last_error()))
        }
    }
}

#[test]
fn the_leg_1_force_is_the_rust_sessions_bit_for_bit() {
    let s = paper_session();
    let act1 = cstr("act1");
    let mut force = f64::NAN;
    // SAFETY: live handle, valid string, valid out pointer.
    unsafe {
        assert_eq!(symbody_session_advance_to(s, 1.0), OK, "{}", last_error());
        assert_eq!(symbody_session_t(s), 1.0);
        assert_eq!(
            symbody_session_driver_effort(s, act1.as_ptr(), &mut force),
            OK,
            "{}",
            last_error()
        );
    }
    let rust = paper_leg1_force_at_1s(&symbody_mechanisms::REGISTRY).unwrap();
    assert_eq!(
        force.to_bits(),
        rust.to_bits(),
        "C ABI {force} vs Rust {rust}"
    );

    // The rest of the state agrees with a Rust session advanced the same way.
    let mut r = Session::new(
        &symbody_mechanisms::REGISTRY,
        "stewart_6_6",
        Settings::default(),
    )
    .unwrap();
    r.advance_to(1.0).unwrap();
    let n = r.q().len();
    let (mut q, mut qd) = (vec![0.0; n], vec![0.0; n]);
    let mut lambda = vec![0.0; r.info().n_constraints];
    let mut efforts = [0.0; 6];
    let mut written = 0;
    let (mut f, mut m) = ([0.0; 3], [0.0; 3]);
    let sph = cstr("upper_sph1");
    // SAFETY: live handle, buffers of the stated lengths.
    unsafe {
        assert_eq!(symbody_session_q(s, q.as_mut_ptr(), n), OK);
        assert_eq!(symbody_session_qd(s, qd.as_mut_ptr(), n), OK);
        let nl = lambda.len();
        assert_eq!(symbody_session_multipliers(s, lambda.as_mut_ptr(), nl), OK);
        assert_eq!(
            symbody_session_driver_efforts(s, efforts.as_mut_ptr(), 6, &mut written),
            OK
        );
        assert_eq!(
            symbody_session_joint_wrench(s, sph.as_ptr(), f.as_mut_ptr(), m.as_mut_ptr()),
            OK,
            "{}",
            last_error()
        );
    }
    assert_eq!(q, r.q());
    assert_eq!(qd, r.qd());
    assert_eq!(lambda, r.multipliers().unwrap());
    assert_eq!(written, 6);
    let mut rust_efforts = [0.0; 6];
    assert_eq!(r.driver_efforts(&mut rust_efforts).unwrap(), 6);
    assert_eq!(efforts, rust_efforts);
    assert_eq!(efforts[0].to_bits(), rust.to_bits());
    let w = r.joint_wrench("upper_sph1").unwrap();
    assert_eq!((f, m), (w.force, w.moment));

    // One more step moves time by the nominal step.
    // SAFETY: live handle, freed once.
    unsafe {
        assert_eq!(symbody_session_step(s), OK);
        assert!((symbody_session_t(s) - 1.001).abs() < 1e-12);
        symbody_session_free(s);
    }
}

#[test]
fn the_mechanism_functions_are_the_generated_code() {
    // SAFETY: index in range; static strings.
    let names: Vec<String> = (0..symbody_mechanism_count())
        .map(|i| unsafe { CStr::from_ptr(symbody_mechanism_name(i)) })
        .map(|c| c.to_str().unwrap().to_string())
        .collect();
    let registry = symbody_mechanisms::REGISTRY.names();
    assert_eq!(names, registry);
    assert!(symbody_mechanism_name(names.len()).is_null());
    assert!(last_error().contains("mechanism index"), "{}", last_error());

    for (code, f) in [
        (1, symbody_runtime::Formulation::Paper),
        (2, symbody_runtime::Formulation::Exact),
    ] {
        let m = mechanism("stewart_6_6", code).unwrap();
        let rust = symbody_mechanisms::find("stewart_6_6")
            .unwrap()
            .mechanism(f)
            .unwrap();
        let info = rust.info();
        // SAFETY: live handle; every buffer has the length passed with it.
        unsafe {
            assert_eq!(symbody_mechanism_formulation(m), code);
            let (n, nc) = (
                symbody_mechanism_n_coords(m),
                symbody_mechanism_n_constraints(m),
            );
            assert_eq!((n, nc), (info.n_coords, info.n_constraints));
            let nnz = symbody_mechanism_phi_q_nnz(m);
            let mnz = symbody_mechanism_mass_nnz(m);
            assert_eq!((nnz, mnz), (info.phi_q_nnz(), info.mass_nnz()));

            let (mut rows, mut cols) = (vec![0u32; nnz], vec![0u32; nnz]);
            let rc = symbody_mechanism_phi_q_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), nnz);
            assert_eq!(rc, OK);
            assert_eq!((&rows[..], &cols[..]), (info.phi_q_rows, info.phi_q_cols));
            let (mut rows, mut cols) = (vec![0u32; mnz], vec![0u32; mnz]);
            let rc = symbody_mechanism_mass_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), mnz);
            assert_eq!(rc, OK);
            assert_eq!((&rows[..], &cols[..]), (info.mass_rows, info.mass_cols));

            // A longer buffer is fine; the extra entries are left alone.
            let mut q = vec![7.0; n + 2];
            assert_eq!(symbody_mechanism_q0(m, q.as_mut_ptr(), n + 2), OK);
            assert_eq!(&q[..n], info.q0);
            assert_eq!(&q[n..], [7.0, 7.0]);
            q.truncate(n);
            // A state off the initial pose, so nothing is trivially zero.
            let qd: Vec<f64> = (0..n).map(|i| 0.01 * (i as f64 + 1.0)).collect();
            for (i, x) in q.iter_mut().enumerate() {
                *x += 1e-3 * (i as f64).sin();
            }
            let t = 0.3;
            let mut c = vec![0.0; nc];
            let mut r = vec![0.0; nc];
            assert_eq!(
                symbody_mechanism_phi(m, q.as_ptr(), n, t, c.as_mut_ptr(), nc),
                OK
            );
            rust.phi(&q, t, &mut r);
            assert_eq!(c, r);
            let (mut c, mut r) = (vec![0.0; nnz], vec![0.0; nnz]);
            assert_eq!(
                symbody_mechanism_phi_q(m, q.as_ptr(), n, t, c.as_mut_ptr(), nnz),
                OK
            );
            rust.phi_q(&q, t, &mut r);
            assert_eq!(c, r);
            let (mut c, mut r) = (vec![0.0; nc], vec![0.0; nc]);
            let rc =
                symbody_mechanism_gamma(m, q.as_ptr(), n, qd.as_ptr(), n, t, c.as_mut_ptr(), nc);
            assert_eq!(rc, OK);
            rust.gamma(&q, &qd, t, &mut r);
            assert_eq!(c, r);
            let (mut c, mut r) = (vec![0.0; mnz], vec![0.0; mnz]);
            assert_eq!(
                symbody_mechanism_mass(m, q.as_ptr(), n, c.as_mut_ptr(), mnz),
                OK
            );
            rust.mass(&q, &mut r);
            assert_eq!(c, r);
            let (mut c, mut r) = (vec![0.0; n], vec![0.0; n]);
            let rc =
                symbody_mechanism_force(m, q.as_ptr(), n, qd.as_ptr(), n, t, c.as_mut_ptr(), n);
            assert_eq!(rc, OK);
            rust.force(&q, &qd, t, &mut r);
            assert_eq!(c, r);

            let drivers: Vec<String> = (0..symbody_mechanism_driver_count(m))
                .map(|i| CStr::from_ptr(symbody_mechanism_driver_name(m, i)))
                .map(|c| c.to_str().unwrap().to_string())
                .collect();
            assert_eq!(drivers, ["act1", "act2", "act3", "act4", "act5", "act6"]);
            assert!(symbody_mechanism_driver_name(m, 6).is_null());
            symbody_mechanism_free(m);
        }
    }
}

#[test]
fn unknown_names_are_errors_that_list_the_known_ones() {
    let (rc, msg) = mechanism("stewart", 0).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::UnknownName));
    assert!(
        msg.contains("stewart_6_6") && msg.contains("four_bar"),
        "{msg}"
    );

    let mut s = null_mut();
    let name = cstr("no_such_thing");
    // SAFETY: valid string and out pointer.
    let rc = unsafe { symbody_session_new(name.as_ptr(), 0, -0.05, 1e-3, &mut s) };
    assert_eq!(rc, status(SymbodyStatus::UnknownName));
    assert!(s.is_null());
    assert!(last_error().contains("stewart_6_6"), "{}", last_error());

    let s = paper_session();
    let act9 = cstr("act9");
    let mut out = 0.0;
    let (mut f, mut m) = ([0.0; 3], [0.0; 3]);
    // SAFETY: live handle, valid strings and out pointers; freed once.
    unsafe {
        let rc = symbody_session_driver_effort(s, act9.as_ptr(), &mut out);
        assert_eq!(rc, status(SymbodyStatus::UnknownName));
        assert!(last_error().contains("act1"), "{}", last_error());
        let rc = symbody_session_joint_wrench(s, act9.as_ptr(), f.as_mut_ptr(), m.as_mut_ptr());
        assert_eq!(rc, status(SymbodyStatus::UnknownName));
        // A joint that is not a driver has no driver effort.
        let sph = cstr("upper_sph1");
        let rc = symbody_session_driver_effort(s, sph.as_ptr(), &mut out);
        assert_eq!(
            rc,
            status(SymbodyStatus::InvalidArgument),
            "{}",
            last_error()
        );
        symbody_session_free(s);
    }
}

#[test]
fn bad_settings_and_formulations_are_invalid_arguments() {
    let name = cstr("stewart_6_6");
    let mut s = null_mut();
    for (formulation, alpha, step, what) in [
        (3, -0.05, 1e-3, "formulation"),
        (-1, -0.05, 1e-3, "formulation"),
        (0, 0.5, 1e-3, "alpha"),
        (0, f64::NAN, 1e-3, "alpha"),
        (0, -0.05, 0.0, "step"),
        (0, -0.05, f64::INFINITY, "step"),
    ] {
        // SAFETY: valid string and out pointer.
        let rc = unsafe { symbody_session_new(name.as_ptr(), formulation, alpha, step, &mut s) };
        assert_eq!(rc, status(SymbodyStatus::InvalidArgument), "{what}");
        assert!(s.is_null());
        assert!(last_error().contains(what), "{what}: {}", last_error());
    }
    let (rc, _) = mechanism("stewart_6_6", 7).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::InvalidArgument));

    let session = paper_session();
    // SAFETY: live handle; freed once.
    unsafe {
        for t in [f64::NAN, f64::INFINITY, -1.0] {
            let rc = symbody_session_advance_to(session, t);
            assert_eq!(rc, status(SymbodyStatus::InvalidArgument), "t = {t}");
        }
        assert_eq!(
            symbody_session_t(session),
            0.0,
            "a refused call leaves the session alone"
        );
        symbody_session_free(session);
    }
    // Not UTF-8.
    let bad = [0xffu8 as c_char, 0];
    // SAFETY: NUL-terminated.
    let rc = unsafe { symbody_session_new(bad.as_ptr(), 0, -0.05, 1e-3, &mut s) };
    assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
    assert!(last_error().contains("UTF-8"), "{}", last_error());
}

#[test]
fn null_pointers_are_errors() {
    let null_status = status(SymbodyStatus::NullPointer);
    let name = cstr("stewart_6_6");
    let mut buf = [0.0; 1000];
    let b = buf.as_mut_ptr();
    let q = b as *const f64;
    let mut out = 0.0;
    let mut n = 0usize;
    let mut s = null_mut();
    let mut m = null_mut();
    // SAFETY: every non-null pointer is valid; the null ones are what is tested.
    unsafe {
        assert_eq!(
            symbody_session_new(null(), 0, -0.05, 1e-3, &mut s),
            null_status
        );
        assert!(last_error().contains("`name`"), "{}", last_error());
        assert_eq!(
            symbody_session_new(name.as_ptr(), 0, -0.05, 1e-3, null_mut()),
            null_status
        );
        assert!(last_error().contains("`out`"), "{}", last_error());
        assert_eq!(symbody_mechanism_new(null(), 0, &mut m), null_status);
        assert_eq!(
            symbody_mechanism_new(name.as_ptr(), 0, null_mut()),
            null_status
        );

        // A null handle.
        let ns: *mut SymbodySession = null_mut();
        assert_eq!(symbody_session_step(ns), null_status);
        assert!(last_error().contains("`session`"), "{}", last_error());
        assert_eq!(symbody_session_advance_to(ns, 1.0), null_status);
        assert!(symbody_session_t(ns).is_nan());
        assert_eq!(symbody_session_q(ns, b, 64), null_status);
        assert_eq!(symbody_session_qd(ns, b, 64), null_status);
        assert_eq!(symbody_session_multipliers(ns, b, 64), null_status);
        let act1 = cstr("act1");
        assert_eq!(
            symbody_session_driver_effort(ns, act1.as_ptr(), &mut out),
            null_status
        );
        assert_eq!(
            symbody_session_driver_efforts(ns, b, 64, &mut n),
            null_status
        );
        let (f, mo) = (b, b.add(3));
        assert_eq!(
            symbody_session_joint_wrench(ns, act1.as_ptr(), f, mo),
            null_status
        );
        assert_eq!(symbody_session_mechanism(ns, &mut m), null_status);
        symbody_session_free(ns);

        let nm: *const SymbodyMechanism = null();
        assert_eq!(symbody_mechanism_n_coords(nm), 0);
        assert!(last_error().contains("`mechanism`"), "{}", last_error());
        assert_eq!(symbody_mechanism_n_constraints(nm), 0);
        assert_eq!(symbody_mechanism_phi_q_nnz(nm), 0);
        assert_eq!(symbody_mechanism_mass_nnz(nm), 0);
        assert_eq!(symbody_mechanism_driver_count(nm), 0);
        assert_eq!(symbody_mechanism_formulation(nm), -1);
        assert!(symbody_mechanism_driver_name(nm, 0).is_null());
        assert_eq!(symbody_mechanism_q0(nm, b, 64), null_status);
        assert_eq!(
            symbody_mechanism_phi(nm, q, 64, 0.0, &mut out, 1),
            null_status
        );
        symbody_mechanism_free(null_mut());

        // Null buffers with a live handle.
        let s = paper_session();
        assert_eq!(symbody_session_q(s, null_mut(), 64), null_status);
        assert!(last_error().contains("`buf`"), "{}", last_error());
        assert_eq!(
            symbody_session_driver_effort(s, null(), &mut out),
            null_status
        );
        assert_eq!(
            symbody_session_driver_effort(s, act1.as_ptr(), null_mut()),
            null_status
        );
        assert_eq!(
            symbody_session_driver_efforts(s, b, 64, null_mut()),
            null_status
        );
        assert_eq!(
            symbody_session_joint_wrench(s, act1.as_ptr(), null_mut(), mo),
            null_status
        );
        assert_eq!(
            symbody_session_joint_wrench(s, act1.as_ptr(), f, null_mut()),
            null_status
        );
        let mut sm = null_mut();
        assert_eq!(symbody_session_mechanism(s, &mut sm), OK);
        let nc = symbody_mechanism_n_coords(sm);
        assert_eq!(
            symbody_mechanism_phi(sm, null(), nc, 0.0, b, 64),
            null_status
        );
        assert!(last_error().contains("`q`"), "{}", last_error());
        let mut big = vec![0.0; 1000];
        let rc = symbody_mechanism_gamma(sm, q, 1000, null(), 1000, 0.0, big.as_mut_ptr(), 1000);
        assert_eq!(rc, null_status);
        assert!(last_error().contains("`qd`"), "{}", last_error());
        let mut rows = [0u32; 1000];
        let rc = symbody_mechanism_phi_q_pattern(sm, rows.as_mut_ptr(), null_mut(), 1000);
        assert_eq!(rc, null_status);
        assert!(last_error().contains("`cols`"), "{}", last_error());
        // A misaligned pointer is refused like a null one.
        let misaligned = (b as *mut u8).add(1) as *mut f64;
        assert_eq!(symbody_session_q(s, misaligned, 8), null_status);
        symbody_mechanism_free(sm);
        symbody_session_free(s);
    }
}

#[test]
fn short_buffers_are_errors_that_say_what_is_needed() {
    let too_short = status(SymbodyStatus::BufferTooShort);
    let s = paper_session();
    let mut m = null_mut();
    // SAFETY: live handles; every buffer is at least as long as the length passed with it.
    unsafe {
        assert_eq!(symbody_session_mechanism(s, &mut m), OK);
        let (n, nc) = (
            symbody_mechanism_n_coords(m),
            symbody_mechanism_n_constraints(m),
        );
        let nnz = symbody_mechanism_phi_q_nnz(m);
        let mut buf = vec![0.0; 1000];
        let b = buf.as_mut_ptr();
        assert_eq!(symbody_session_q(s, b, n - 1), too_short);
        assert!(
            last_error().contains(&format!("length {}; this call needs {n}", n - 1)),
            "{}",
            last_error()
        );
        assert_eq!(symbody_session_qd(s, b, 0), too_short);
        assert_eq!(symbody_session_multipliers(s, b, nc - 1), too_short);
        let mut written = 99;
        assert_eq!(
            symbody_session_driver_efforts(s, b, 5, &mut written),
            too_short
        );
        assert_eq!(written, 6, "the number needed");
        assert_eq!(symbody_mechanism_q0(m, b, n - 1), too_short);

        let mut q = vec![0.0; n];
        assert_eq!(symbody_mechanism_q0(m, q.as_mut_ptr(), n), OK);
        let mut out = vec![0.0; 1000];
        let o = out.as_mut_ptr();
        // Short input.
        assert_eq!(
            symbody_mechanism_phi(m, q.as_ptr(), n - 1, 0.0, o, 1000),
            too_short
        );
        assert!(last_error().contains("`q`"), "{}", last_error());
        let rc = symbody_mechanism_gamma(m, q.as_ptr(), n, q.as_ptr(), n - 1, 0.0, o, 1000);
        assert_eq!(rc, too_short);
        assert!(last_error().contains("`qd`"), "{}", last_error());
        // Short outputs.
        assert_eq!(
            symbody_mechanism_phi(m, q.as_ptr(), n, 0.0, o, nc - 1),
            too_short
        );
        assert!(last_error().contains("`out`"), "{}", last_error());
        assert_eq!(
            symbody_mechanism_phi_q(m, q.as_ptr(), n, 0.0, o, nnz - 1),
            too_short
        );
        let mnz = symbody_mechanism_mass_nnz(m);
        assert_eq!(
            symbody_mechanism_mass(m, q.as_ptr(), n, o, mnz - 1),
            too_short
        );
        let rc = symbody_mechanism_force(m, q.as_ptr(), n, q.as_ptr(), n, 0.0, o, n - 1);
        assert_eq!(rc, too_short);
        let (mut rows, mut cols) = (vec![0u32; nnz], vec![0u32; nnz]);
        let rc = symbody_mechanism_phi_q_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), nnz - 1);
        assert_eq!(rc, too_short);
        symbody_mechanism_free(m);
        symbody_session_free(s);
    }
}

/// Every entry point fed garbage (nulls, zero lengths, NaN, out-of-range codes) answers
/// with a status: none reports a caught panic, and nothing escapes the boundary.
#[test]
fn garbage_in_is_a_status_out_never_a_panic() {
    let panic = status(SymbodyStatus::Panic);
    let result = std::panic::catch_unwind(|| {
        let mut statuses = Vec::new();
        let s = paper_session();
        let mut m = null_mut();
        let name = cstr("stewart_6_6");
        let empty = cstr("");
        let mut buf = vec![0.0; 1000];
        let b = buf.as_mut_ptr();
        let mut n = 0usize;
        let mut x = 0.0;
        // SAFETY: live handles; every non-null buffer is as long as its length.
        unsafe {
            assert_eq!(symbody_mechanism_new(name.as_ptr(), 0, &mut m), OK);
            statuses.push(symbody_session_new(
                empty.as_ptr(),
                0,
                -0.05,
                1e-3,
                &mut null_mut(),
            ));
            statuses.push(symbody_session_new(
                name.as_ptr(),
                i32::MIN,
                0.0,
                1e-3,
                &mut null_mut(),
            ));
            statuses.push(symbody_session_new(
                name.as_ptr(),
                0,
                -1e300,
                -1e300,
                &mut null_mut(),
            ));
            statuses.push(symbody_session_new(
                name.as_ptr(),
                0,
                -0.05,
                1e-300,
                &mut null_mut(),
            ));
            statuses.push(symbody_mechanism_new(empty.as_ptr(), 0, &mut null_mut()));
            statuses.push(symbody_session_advance_to(s, f64::NEG_INFINITY));
            statuses.push(symbody_session_advance_to(s, 1e-12));
            statuses.push(symbody_session_q(s, b, 0));
            statuses.push(symbody_session_driver_efforts(s, b, 0, &mut n));
            statuses.push(symbody_session_driver_effort(s, empty.as_ptr(), &mut x));
            let (f, mo) = (b, b.add(3));
            statuses.push(symbody_session_joint_wrench(s, empty.as_ptr(), f, mo));
            statuses.push(symbody_mechanism_phi(m, b, 0, f64::NAN, b.add(500), 0));
            statuses.push(symbody_mechanism_phi_q(
                m,
                b,
                usize::MAX,
                f64::NAN,
                null_mut(),
                0,
            ));
            statuses.push(symbody_mechanism_mass(m, b, 0, b.add(500), usize::MAX));
            statuses.push(symbody_mechanism_phi_q_pattern(
                m,
                null_mut(),
                null_mut(),
                0,
            ));
            let mut rows = [0u32; 4];
            let r = rows.as_mut_ptr();
            statuses.push(symbody_mechanism_mass_pattern(m, r, r, 0));
            assert!(symbody_mechanism_name(usize::MAX).is_null());
            assert!(symbody_mechanism_driver_name(m, usize::MAX).is_null());
            // NaN inputs evaluate (the generated code is branch-free) rather than fail.
            std::slice::from_raw_parts_mut(b, 100).fill(f64::NAN);
            let rc = symbody_mechanism_phi(m, b, 100, f64::NAN, b.add(500), 400);
            statuses.push(rc);
            symbody_mechanism_free(m);
            symbody_session_free(s);
        }
        statuses
    });
    let statuses = result.expect("no panic crosses the boundary");
    assert!(
        statuses.iter().all(|&s| s != panic && (0..=6).contains(&s)),
        "{statuses:?}: {}",
        last_error()
    );
    assert!(
        statuses[..statuses.len() - 1].iter().all(|&s| s != OK),
        "{statuses:?}"
    );
}

/// The loads' Jacobians through C equal the Rust trait's, bit for bit, on a mechanism with
/// springs and dampers; one without has zero counts and accepts NULL outputs; a short buffer
/// is an error.
#[test]
fn load_jacobians_match_rust_and_may_be_empty() {
    let m = mechanism("oscillators", 0).unwrap();
    let rust = symbody_mechanisms::find("oscillators")
        .unwrap()
        .default_mechanism();
    let info = rust.info();
    // SAFETY: live handles; every buffer has the length passed with it; freed once.
    unsafe {
        let (nq, nqd) = (
            symbody_mechanism_force_q_nnz(m),
            symbody_mechanism_force_qd_nnz(m),
        );
        assert_eq!(
            (nq, nqd),
            (info.force_q_rows.len(), info.force_qd_rows.len())
        );
        assert!(nq > 0 && nqd > 0);
        let (mut rows, mut cols) = (vec![0u32; nq], vec![0u32; nq]);
        let rc = symbody_mechanism_force_q_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), nq);
        assert_eq!(rc, OK);
        assert_eq!(
            (&rows[..], &cols[..]),
            (info.force_q_rows, info.force_q_cols)
        );
        let (mut rows, mut cols) = (vec![0u32; nqd], vec![0u32; nqd]);
        let rc = symbody_mechanism_force_qd_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), nqd);
        assert_eq!(rc, OK);
        assert_eq!(
            (&rows[..], &cols[..]),
            (info.force_qd_rows, info.force_qd_cols)
        );

        let n = info.n_coords;
        let q = info.q0.to_vec();
        let qd: Vec<f64> = (0..n).map(|i| 0.01 * (i as f64 + 1.0)).collect();
        let (mut cq, mut cqd) = (vec![0.0; nq], vec![0.0; nqd]);
        let rc = symbody_mechanism_force_jacobian(
            m,
            q.as_ptr(),
            n,
            qd.as_ptr(),
            n,
            0.3,
            cq.as_mut_ptr(),
            nq,
            cqd.as_mut_ptr(),
            nqd,
        );
        assert_eq!(rc, OK, "{}", last_error());
        let (mut rq, mut rqd) = (vec![0.0; nq], vec![0.0; nqd]);
        rust.force_jacobian(&q, &qd, 0.3, &mut rq, &mut rqd);
        assert_eq!((&cq, &cqd), (&rq, &rqd));
        let mut short = vec![0.0; nq - 1];
        let rc = symbody_mechanism_force_jacobian(
            m,
            q.as_ptr(),
            n,
            qd.as_ptr(),
            n,
            0.3,
            short.as_mut_ptr(),
            nq - 1,
            rqd.as_mut_ptr(),
            nqd,
        );
        assert_eq!(rc, status(SymbodyStatus::BufferTooShort));
        assert!(last_error().contains("dq"), "{}", last_error());
        symbody_mechanism_free(m);

        let m = mechanism("four_bar", 0).unwrap();
        assert_eq!(symbody_mechanism_force_q_nnz(m), 0);
        assert_eq!(symbody_mechanism_force_qd_nnz(m), 0);
        let q = symbody_mechanisms::find("four_bar")
            .unwrap()
            .default_mechanism()
            .info()
            .q0;
        let rc = symbody_mechanism_force_jacobian(
            m,
            q.as_ptr(),
            q.len(),
            q.as_ptr(),
            q.len(),
            0.0,
            null_mut(),
            0,
            null_mut(),
            0,
        );
        assert_eq!(rc, OK, "{}", last_error());
        symbody_mechanism_free(m);
    }
}

/// The N-four-bar lies flat at t ≈ 0.70 and 1.22 s (IFToMM A02): with the flag a C session
/// steps across both and gives multipliers at every 10 ms output, as the Rust session does
/// (tests/singular_positions.rs sweeps the steps there); unknown flag bits are refused.
#[test]
fn a_session_with_the_flag_crosses_singular_positions() {
    let name = cstr("n_four_bar_2");
    for step in [5e-4, 1e-4] {
        let mut s = null_mut();
        // SAFETY: valid string and out pointer.
        let rc = unsafe {
            symbody_session_new_ex(
                name.as_ptr(),
                0,
                0.0,
                step,
                SYMBODY_CROSS_SINGULAR_POSITIONS | SYMBODY_PROJECT_VELOCITIES,
                &mut s,
            )
        };
        assert_eq!(rc, OK, "{}", last_error());
        // NaN until written: more room than the mechanism's rows.
        let mut lambda = vec![f64::NAN; 64];
        for k in 1..=150 {
            // SAFETY: live handle, buffer of the given length, valid out pointer.
            unsafe {
                let rc = symbody_session_advance_to(s, k as f64 * 0.01);
                assert_eq!(rc, OK, "step {step}, output {k}: {}", last_error());
                let rc = symbody_session_multipliers(s, lambda.as_mut_ptr(), lambda.len());
                assert_eq!(rc, OK, "step {step}, output {k}: {}", last_error());
            }
        }
        let rows = lambda.iter().take_while(|l| l.is_finite()).count();
        assert!(rows > 20, "{rows} multipliers written");
        // SAFETY: live handle, freed once.
        unsafe { symbody_session_free(s) };
    }
    let mut s = null_mut();
    // SAFETY: valid string and out pointer.
    let rc = unsafe { symbody_session_new_ex(name.as_ptr(), 0, 0.0, 1e-3, 4, &mut s) };
    assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
    assert!(
        s.is_null() && last_error().contains("flags"),
        "{}",
        last_error()
    );
}

/// A fresh folder under the system's temporary one, for this test alone.
fn temp_folder(test: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-capi-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn shipped(file: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../mechanisms")
        .join(file)
}

fn from_file(path: &str, formulation: c_int) -> Result<*mut SymbodyMechanism, (c_int, String)> {
    let mut m = null_mut();
    let path = cstr(path);
    // SAFETY: valid string and out pointer.
    match unsafe { symbody_mechanism_from_file(path.as_ptr(), formulation, &mut m) } {
        OK => Ok(m),
        rc => {
            assert!(m.is_null(), "a failed call leaves *out NULL");
            Err((rc, last_error()))
        }
    }
}

/// The largest difference of `c` from `r`, relative to the larger of each entry and the
/// largest entry of `r` (so entries that vanish are compared at the vector's scale).
fn relative(c: &[f64], r: &[f64]) -> f64 {
    assert_eq!(c.len(), r.len());
    let scale = r.iter().fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()));
    c.iter()
        .zip(r)
        .map(|(a, b)| (a - b).abs() / scale.max(b.abs()))
        .fold(0.0, f64::max)
}

#[test]
fn a_mechanism_file_runs_interpreted_with_the_compiled_numbers() {
    let dir = temp_folder("file");
    // Renamed and without `.toml`: `_from_file` takes any path.
    let path = dir.join("my_crank");
    std::fs::copy(shipped("slider_crank.toml"), &path).unwrap();
    let path = path.to_str().unwrap().to_string();
    let compiled = mechanism("slider_crank", 0).unwrap();
    let m = from_file(&path, 0).unwrap_or_else(|(rc, msg)| panic!("{rc}: {msg}"));
    let rust = symbody_mechanisms::find("slider_crank")
        .unwrap()
        .default_mechanism();
    let info = rust.info();
    let mut worst = 0.0f64;
    // SAFETY: live handles; every buffer has the length passed with it.
    unsafe {
        assert!(symbody_mechanism_source(compiled).is_null());
        let source = CStr::from_ptr(symbody_mechanism_source(m))
            .to_str()
            .unwrap();
        assert_eq!(source, path);
        assert_eq!(
            symbody_mechanism_formulation(m),
            symbody_mechanism_formulation(compiled)
        );
        let (n, nc) = (
            symbody_mechanism_n_coords(m),
            symbody_mechanism_n_constraints(m),
        );
        assert_eq!((n, nc), (info.n_coords, info.n_constraints));
        let (nnz, mnz) = (
            symbody_mechanism_phi_q_nnz(m),
            symbody_mechanism_mass_nnz(m),
        );
        assert_eq!((nnz, mnz), (info.phi_q_nnz(), info.mass_nnz()));
        let (mut rows, mut cols) = (vec![0u32; nnz], vec![0u32; nnz]);
        let rc = symbody_mechanism_phi_q_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), nnz);
        assert_eq!(rc, OK);
        assert_eq!((&rows[..], &cols[..]), (info.phi_q_rows, info.phi_q_cols));
        let (mut rows, mut cols) = (vec![0u32; mnz], vec![0u32; mnz]);
        let rc = symbody_mechanism_mass_pattern(m, rows.as_mut_ptr(), cols.as_mut_ptr(), mnz);
        assert_eq!(rc, OK);
        assert_eq!((&rows[..], &cols[..]), (info.mass_rows, info.mass_cols));

        let mut q0 = vec![0.0; n];
        assert_eq!(symbody_mechanism_q0(m, q0.as_mut_ptr(), n), OK);
        assert!(relative(&q0, info.q0) <= 1e-13);
        for k in 0..4 {
            // The initial pose and states off it, so nothing is trivially zero.
            let s = k as f64;
            let q: Vec<f64> = (0..n)
                .map(|i| info.q0[i] + 0.05 * s * (i as f64 + s).sin())
                .collect();
            let qd: Vec<f64> = (0..n).map(|i| 0.3 * s * (i as f64 - s).cos()).collect();
            let t = 0.1 * s;
            let both = |f: &dyn Fn(*const SymbodyMechanism, &mut [f64]) -> c_int, len: usize| {
                let (mut c, mut r) = (vec![f64::NAN; len], vec![f64::NAN; len]);
                assert_eq!(f(m, &mut c), OK, "{}", last_error());
                assert_eq!(f(compiled, &mut r), OK, "{}", last_error());
                relative(&c, &r)
            };
            worst = worst.max(both(
                &|h, o| symbody_mechanism_phi(h, q.as_ptr(), n, t, o.as_mut_ptr(), o.len()),
                nc,
            ));
            worst = worst.max(both(
                &|h, o| symbody_mechanism_phi_q(h, q.as_ptr(), n, t, o.as_mut_ptr(), o.len()),
                nnz,
            ));
            worst = worst.max(both(
                &|h, o| {
                    let len = o.len();
                    symbody_mechanism_gamma(
                        h,
                        q.as_ptr(),
                        n,
                        qd.as_ptr(),
                        n,
                        t,
                        o.as_mut_ptr(),
                        len,
                    )
                },
                nc,
            ));
            worst = worst.max(both(
                &|h, o| symbody_mechanism_mass(h, q.as_ptr(), n, o.as_mut_ptr(), o.len()),
                mnz,
            ));
            worst = worst.max(both(
                &|h, o| {
                    let len = o.len();
                    symbody_mechanism_force(
                        h,
                        q.as_ptr(),
                        n,
                        qd.as_ptr(),
                        n,
                        t,
                        o.as_mut_ptr(),
                        len,
                    )
                },
                n,
            ));
        }
        symbody_mechanism_free(m);
        symbody_mechanism_free(compiled);
    }
    eprintln!("slider_crank from a file vs compiled: largest relative difference {worst:.2e}");
    assert!(worst <= 1e-13, "{worst:e}");

    // `_from_file` never looks a name up in the registry: `slider_crank` is a file here.
    let (rc, msg) = from_file("slider_crank", 0).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::FileNotFound), "{msg}");
    assert!(msg.contains("slider_crank"), "{msg}");
    // A formulation the file does not list (it has `exact` only), and no formulation.
    let (rc, msg) = from_file(&path, 1).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::InvalidArgument), "{msg}");
    assert!(msg.contains("paper"), "{msg}");
    let (rc, msg) = from_file(&path, 7).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::InvalidArgument), "{msg}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_session_runs_from_a_file() {
    let dir = temp_folder("session");
    let path = dir.join("crank_copy.toml");
    std::fs::copy(shipped("slider_crank.toml"), &path).unwrap();
    let path = cstr(path.to_str().unwrap());
    let d = Settings::default();
    let name = cstr("slider_crank");
    let (mut compiled, mut by_name, mut by_file) = (null_mut(), null_mut(), null_mut());
    // SAFETY: valid strings, out pointers and handles; buffers of the lengths passed.
    unsafe {
        let rc = symbody_session_new(name.as_ptr(), 0, d.alpha, d.step, &mut compiled);
        assert_eq!(rc, OK, "{}", last_error());
        // A `.toml` path given where a name goes is a file too.
        let rc = symbody_session_new(path.as_ptr(), 0, d.alpha, d.step, &mut by_name);
        assert_eq!(rc, OK, "{}", last_error());
        let rc = symbody_session_from_file(path.as_ptr(), 0, d.alpha, d.step, 0, &mut by_file);
        assert_eq!(rc, OK, "{}", last_error());
        let mut m = null_mut();
        assert_eq!(symbody_session_mechanism(by_file, &mut m), OK);
        let source = CStr::from_ptr(symbody_mechanism_source(m));
        assert_eq!(source, path.as_c_str());
        let n = symbody_mechanism_n_coords(m);
        symbody_mechanism_free(m);
        let mut worst = 0.0f64;
        let mut r = vec![0.0; n];
        assert_eq!(symbody_session_advance_to(compiled, 0.2), OK);
        assert_eq!(symbody_session_q(compiled, r.as_mut_ptr(), n), OK);
        for s in [by_name, by_file] {
            let mut c = vec![0.0; n];
            assert_eq!(symbody_session_advance_to(s, 0.2), OK, "{}", last_error());
            assert_eq!(symbody_session_t(s), 0.2);
            assert_eq!(symbody_session_q(s, c.as_mut_ptr(), n), OK);
            worst = worst.max(relative(&c, &r));
            symbody_session_free(s);
        }
        symbody_session_free(compiled);
        eprintln!("slider_crank session from a file vs compiled at 0.2 s: q within {worst:.2e}");
        assert!(worst <= 1e-10, "{worst:e}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_files_are_statuses_with_messages_naming_them() {
    let dir = temp_folder("bad");
    let missing = dir.join("missing.toml");
    let broken = dir.join("broken.toml");
    std::fs::write(&broken, "name = \"broken\"\n[bodies.arm\nmass = 1.0\n").unwrap();
    let binary = dir.join("binary.toml");
    std::fs::write(&binary, b"name = \"x\"\n# caf\xe9\n").unwrap();
    let cases = [
        (&missing, SymbodyStatus::FileNotFound, "no such file"),
        (&dir, SymbodyStatus::FileNotFound, "folder"),
        (&broken, SymbodyStatus::InvalidFile, ":2:"),
        (&binary, SymbodyStatus::InvalidFile, "line 2, column 6"),
    ];
    for (path, want, says) in cases {
        let p = path.to_str().unwrap();
        let (rc, msg) = from_file(p, 0).unwrap_err();
        assert_eq!(rc, status(want), "{p}: {msg}");
        assert!(msg.contains(p), "the message names {p}: {msg}");
        assert!(msg.contains(says), "{p}: `{says}` in {msg}");
        // The same through a name that is a path, and through the sessions.
        let (rc2, msg2) = mechanism(p, 0).unwrap_err();
        assert_eq!((rc2, &msg2), (rc, &msg));
        let c = cstr(p);
        let mut s = null_mut();
        // SAFETY: valid string and out pointer.
        unsafe {
            assert_eq!(
                symbody_session_from_file(c.as_ptr(), 0, -0.05, 1e-3, 0, &mut s),
                rc
            );
            assert_eq!(last_error(), msg);
            assert_eq!(symbody_session_new(c.as_ptr(), 0, -0.05, 1e-3, &mut s), rc);
            assert_eq!(last_error(), msg);
        }
        assert!(s.is_null());
    }
    let (rc, msg) = from_file("", 0).unwrap_err();
    assert_eq!(rc, status(SymbodyStatus::FileNotFound), "{msg}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Parameters set through C before anything is derived: the same mechanism and session as
/// Rust's `files::with_parameters`, and a wrong name or value is an invalid argument that
/// names the parameter.
#[test]
fn parameters_are_set_before_a_mechanism_or_session_starts() {
    let name = cstr("slider_crank");
    let r = cstr("r");
    let names = [r.as_ptr()];
    let values = [0.12];
    let set = vec![("r".to_string(), 0.12)];
    let rust = symbody::files::with_parameters(&symbody_mechanisms::REGISTRY, "slider_crank", &set)
        .unwrap()
        .default_mechanism();
    let d = Settings::default();
    // SAFETY: valid strings, arrays of `count` entries, out pointers and buffers.
    unsafe {
        let mut m = null_mut();
        let rc = symbody_mechanism_with_parameters(
            name.as_ptr(),
            0,
            names.as_ptr(),
            values.as_ptr(),
            1,
            &mut m,
        );
        assert_eq!(rc, OK, "{}", last_error());
        let n = symbody_mechanism_n_coords(m);
        let mut q0 = vec![0.0; n];
        assert_eq!(symbody_mechanism_q0(m, q0.as_mut_ptr(), n), OK);
        assert_eq!(q0, rust.info().q0, "the q0 of the re-derived file");
        assert_ne!(q0, symbody_mechanisms::slider_crank::exact::INFO.q0);
        symbody_mechanism_free(m);

        let mut s = null_mut();
        let rc = symbody_session_with_parameters(
            name.as_ptr(),
            0,
            d.alpha,
            d.step,
            SYMBODY_PROJECT_VELOCITIES,
            names.as_ptr(),
            values.as_ptr(),
            1,
            &mut s,
        );
        assert_eq!(rc, OK, "{}", last_error());
        assert_eq!(symbody_session_advance_to(s, 0.1), OK, "{}", last_error());
        let mut reference = Session::with_mechanism(
            rust,
            Settings {
                project_velocities: true,
                ..Settings::default()
            },
        )
        .unwrap();
        reference.advance_to(0.1).unwrap();
        let mut q = vec![0.0; n];
        assert_eq!(symbody_session_q(s, q.as_mut_ptr(), n), OK);
        assert_eq!(q, reference.q());
        symbody_session_free(s);

        let bad = cstr("rr");
        let rc = symbody_mechanism_with_parameters(
            name.as_ptr(),
            0,
            [bad.as_ptr()].as_ptr(),
            values.as_ptr(),
            1,
            &mut m,
        );
        assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
        assert!(
            last_error().contains("did you mean `r`?"),
            "{}",
            last_error()
        );
        let rc = symbody_mechanism_with_parameters(
            name.as_ptr(),
            0,
            names.as_ptr(),
            [f64::NAN].as_ptr(),
            1,
            &mut m,
        );
        assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
        assert!(
            last_error().contains("parameter `r` set to NaN"),
            "{}",
            last_error()
        );
        assert!(m.is_null());
    }
}

/// A file's parameters listed through C, by index: the names and values `symbody params`
/// shows (the file's `[parameters]`), each settable by name; an index past the end is an
/// invalid argument, an unknown mechanism an unknown name.
#[test]
fn parameters_are_listed_by_index() {
    let name = cstr("slider_crank");
    let loaded = symbody::files::parameters(&symbody_mechanisms::REGISTRY, "slider_crank").unwrap();
    // SAFETY: valid strings and out pointers.
    unsafe {
        let mut count = 0;
        assert_eq!(symbody_parameter_count(name.as_ptr(), &mut count), OK);
        assert_eq!(count, loaded.parameters.len());
        for (i, p) in loaded.parameters.iter().enumerate() {
            let (mut n, mut v) = (std::ptr::null(), 0.0);
            assert_eq!(symbody_parameter(name.as_ptr(), i, &mut n, &mut v), OK);
            assert_eq!(std::ffi::CStr::from_ptr(n).to_str().unwrap(), p.name);
            assert_eq!(v.to_bits(), p.value.to_bits());
        }
        let (mut n, mut v) = (std::ptr::null(), 0.0);
        let rc = symbody_parameter(name.as_ptr(), count, &mut n, &mut v);
        assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
        assert!(last_error().contains("has 12"), "{}", last_error());
        let rc = symbody_parameter_count(cstr("slider").as_ptr(), &mut count);
        assert_eq!(rc, status(SymbodyStatus::UnknownName));
    }
}

/// The four files a new user wrote from published definitions (examples/mechanisms/) run
/// through the C ABI with nothing built: a session from each file keeps its constraints.
#[test]
fn the_example_files_run_from_c() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/mechanisms");
    let d = Settings::default();
    for stem in [
        "three_rps",
        "rsup_slider_crank",
        "parallelogram_four_bar",
        "bricard_loop",
    ] {
        let path = cstr(dir.join(format!("{stem}.toml")).to_str().unwrap());
        // SAFETY: valid strings, out pointers, handles and buffers of the lengths passed.
        unsafe {
            let mut s = null_mut();
            let rc = symbody_session_from_file(path.as_ptr(), 0, d.alpha, d.step, 0, &mut s);
            assert_eq!(rc, OK, "{stem}: {}", last_error());
            assert_eq!(
                symbody_session_advance_to(s, 0.05),
                OK,
                "{stem}: {}",
                last_error()
            );
            let mut m = null_mut();
            assert_eq!(symbody_session_mechanism(s, &mut m), OK);
            let (n, rows) = (
                symbody_mechanism_n_coords(m),
                symbody_mechanism_n_constraints(m),
            );
            let (mut q, mut phi) = (vec![0.0; n], vec![0.0; rows]);
            assert_eq!(symbody_session_q(s, q.as_mut_ptr(), n), OK);
            let t = symbody_session_t(s);
            assert_eq!(
                symbody_mechanism_phi(m, q.as_ptr(), n, t, phi.as_mut_ptr(), rows),
                OK
            );
            let worst = phi.iter().fold(0.0f64, |w, x| w.max(x.abs()));
            assert!(worst < 1e-8, "{stem}: |Φ| = {worst:e}");
            symbody_mechanism_free(m);
            symbody_session_free(s);
        }
    }
}

#[test]
fn a_controlled_session_is_the_rust_sessions_and_refuses_bad_tolerances() {
    let name = cstr("spherical_pendulum");
    let d = Settings::default();
    // SAFETY: a valid string, out pointers and buffers of the stated sizes.
    unsafe {
        let mut s = null_mut();
        let rc = symbody_session_new_controlled(
            name.as_ptr(),
            0,
            d.alpha,
            d.step,
            1e-6,
            1e-8,
            0,
            &mut s,
        );
        assert_eq!(rc, OK, "{}", last_error());
        assert_eq!(symbody_session_advance_to(s, 0.37), OK, "{}", last_error());
        assert_eq!(symbody_session_t(s), 0.37, "the time asked is landed on");
        let mut reference = Session::new(
            &symbody_mechanisms::REGISTRY,
            "spherical_pendulum",
            Settings {
                tolerances: Some((1e-6, 1e-8)),
                ..Settings::default()
            },
        )
        .unwrap();
        reference.advance_to(0.37).unwrap();
        let n = reference.q().len();
        let mut q = vec![0.0; n];
        assert_eq!(symbody_session_q(s, q.as_mut_ptr(), n), OK);
        assert_eq!(q, reference.q());
        symbody_session_free(s);

        for (rtol, atol) in [(0.0, 1e-8), (1e-6, f64::NAN), (-1.0, 1.0)] {
            let rc = symbody_session_new_controlled(
                name.as_ptr(),
                0,
                d.alpha,
                d.step,
                rtol,
                atol,
                0,
                &mut s,
            );
            assert_eq!(rc, status(SymbodyStatus::InvalidArgument));
            assert!(s.is_null());
            assert!(
                last_error().contains("a tolerance must be positive"),
                "{}",
                last_error()
            );
        }
    }
}
