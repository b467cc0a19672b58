//! Fill-reducing ordering and symbolic factorization of a symmetric sparsity pattern, done
//! once when a solver is built so that numeric factorizations only fill preallocated slots.

use std::collections::BTreeSet;

/// Elimination order and the pattern of the unit lower-triangular factor `L`.
#[derive(Debug, Clone)]
pub(super) struct Symbolic {
    /// `perm[k]` is the original index eliminated at step `k`.
    pub perm: Vec<usize>,
    /// Inverse of `perm`.
    pub iperm: Vec<usize>,
    /// Column `k` of `L` (permuted indices, strictly below the diagonal) is
    /// `row_idx[col_ptr[k]..col_ptr[k + 1]]`, ascending.
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
}

/// Minimum-degree ordering on the explicit elimination graph, after the nodes `first`
/// (eliminated first, in the order given).
///
/// Eliminating a node joins its neighbours into a clique; those neighbours are exactly the
/// node's column of `L`, so the ordering and the symbolic factorization come out together.
/// The graph is explicit (no quotient graph): construction cost is irrelevant at the sizes
/// of mechanisms (hundreds of rows). Ties go to the lowest index, so the result is
/// deterministic.
pub(super) fn minimum_degree(size: usize, edges: &[(usize, usize)], first: &[usize]) -> Symbolic {
    let mut adj: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); size];
    for &(a, b) in edges {
        if a != b {
            adj[a].insert(b);
            adj[b].insert(a);
        }
    }
    let mut eliminated = vec![false; size];
    let mut perm = Vec::with_capacity(size);
    let mut columns: Vec<Vec<usize>> = Vec::with_capacity(size);
    for step in 0..size {
        let v = first.get(step).copied().unwrap_or_else(|| {
            (0..size)
                .filter(|&i| !eliminated[i])
                .min_by_key(|&i| (adj[i].len(), i))
                .expect("a node remains at every step")
        });
        eliminated[v] = true;
        let nbrs: Vec<usize> = adj[v].iter().copied().collect();
        for &a in &nbrs {
            adj[a].remove(&v);
            for &b in &nbrs {
                if a != b {
                    adj[a].insert(b);
                }
            }
        }
        adj[v].clear();
        perm.push(v);
        columns.push(nbrs);
    }
    let mut iperm = vec![0; size];
    for (k, &v) in perm.iter().enumerate() {
        iperm[v] = k;
    }
    let mut col_ptr = Vec::with_capacity(size + 1);
    let mut row_idx = Vec::new();
    col_ptr.push(0);
    for col in &columns {
        let mut rows: Vec<usize> = col.iter().map(|&v| iperm[v]).collect();
        rows.sort_unstable();
        row_idx.extend(rows);
        col_ptr.push(row_idx.len());
    }
    Symbolic {
        perm,
        iperm,
        col_ptr,
        row_idx,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrow_matrix_puts_the_hub_last() {
        // A star graph: eliminating the hub first would fill everything.
        let edges: Vec<_> = (1..6).map(|i| (0, i)).collect();
        let s = minimum_degree(6, &edges, &[]);
        // (With one leaf left the hub and the leaf tie; either order is fill-free.)
        assert!(s.iperm[0] >= 4);
        // No fill: every leaf's column holds only the hub.
        assert_eq!(s.row_idx.len(), 5);
    }

    #[test]
    fn pattern_rows_are_below_diagonal_and_sorted() {
        let edges = [(0, 3), (1, 3), (2, 4), (3, 4), (0, 1)];
        let s = minimum_degree(5, &edges, &[]);
        for k in 0..5 {
            let col = &s.row_idx[s.col_ptr[k]..s.col_ptr[k + 1]];
            assert!(col.windows(2).all(|w| w[0] < w[1]));
            assert!(col.iter().all(|&r| r > k));
        }
    }
}
