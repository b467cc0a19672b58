fn main() {
    for name in ["stewart_6_6", "slider_crank", "ups_stewart"] {
        let path = format!("mechanisms/{name}.toml");
        let text = std::fs::read_to_string(&path).unwrap();
        let model = symbody_codegen::model::load(&path, &text).unwrap();
        let sys = symbody_codegen::equations::build(&model);
        let n = sys.n_coords;
        let pq: Vec<_> = sys.phi_q.iter().map(|e| e.2).collect();
        let d = &sys.dynamics[0];
        let mass: Vec<_> = d.mass.iter().map(|e| e.2).collect();
        let t = |o: &[&[symbody_codegen::expr::Id]]| {
            let tp = symbody_codegen::tape::lower(&sys.arena, n, o);
            (tp.len(), tp.runs())
        };
        println!(
            "{name}: newton {:?} kin {:?} mass {:?} force {:?} phi_q {:?}",
            t(&[&sys.phi, &pq, &mass, &d.force]),
            t(&[&sys.phi, &pq, &sys.phi_t, &sys.gamma]),
            t(&[&mass]),
            t(&[&d.force]),
            t(&[&pq])
        );
    }
}
