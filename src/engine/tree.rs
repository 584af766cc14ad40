//! The dofs' tree walked in dof order with each dof's ancestors at hand, so that loops over
//! ancestors read an array instead of chasing dof_parentid one load after another.

/// Deepest path kept; below it the callers follow dof_parentid.
pub const DEPTH: usize = 64;

/// Whether keeping the path pays in a tree whose sparse inertia has `nm` entries over `nv`
/// dofs: where rows hold at least `per_dof` entries on average. In shallow trees (cheetah,
/// walker: about five) the bookkeeping costs more than the loads it saves.
pub fn deep(nv: usize, nm: usize, per_dof: usize) -> bool {
    nm >= per_dof * nv
}

/// Whether the rows of the sparse inertia (dof_Madr, nM entries) follow the tree as a solve
/// by depth needs: dofs in depth-first order, each row holding the dof and its ancestors
/// (depth + 1 entries), none deeper than DEPTH. A dof's depth is then its row's length less
/// one, and its ancestors are the last dofs before it at each smaller depth.
pub fn rows_by_depth(madr: &[i32], parent: &[i32], nm: usize) -> bool {
    let mut path = [-1i32; DEPTH];
    let nv = madr.len().min(parent.len());
    for i in 0..nv {
        let end = madr.get(i + 1).map_or(nm as i64, |&a| a as i64);
        let len = end - madr[i] as i64;
        if madr[i] < 0 || end > nm as i64 || len < 1 || len > DEPTH as i64 {
            return false;
        }
        let d = len as usize - 1;
        if parent[i] != if d == 0 { -1 } else { path[d - 1] } {
            return false;
        }
        path[d] = i as i32;
    }
    true
}

/// Dofs lie in depth-first order (`abi::consistency` checks it at load), so the ancestors of
/// each dof in turn are the path from its root down to its parent: a stack. A walk visits the
/// dofs either in increasing order (`next`) or in decreasing order (`prev`), not both.
pub struct DofPath {
    path: [u32; DEPTH],
    len: usize,
}

impl Default for DofPath {
    fn default() -> Self {
        Self::new()
    }
}

impl DofPath {
    pub fn new() -> Self {
        DofPath {
            path: [0; DEPTH],
            len: 0,
        }
    }

    /// Moves up to dof `i`, whose parent is `parent`, and gives its ancestors, the root first;
    /// None where the path is not known (deeper than DEPTH, or the order is not depth-first),
    /// and then up to the next root.
    #[inline(always)]
    pub fn next(&mut self, i: usize, parent: i32) -> Option<&[u32]> {
        if parent < 0 {
            self.len = 0;
        } else {
            while self.len > 0 && self.path[self.len - 1] != parent as u32 {
                self.len -= 1;
            }
            if self.len == 0 {
                return None;
            }
        }
        if self.len == DEPTH {
            return None;
        }
        self.path[self.len] = i as u32;
        self.len += 1;
        Some(&self.path[..self.len - 1])
    }

    /// Moves down to dof `i` and gives its ancestors, the root first: pops the path back to
    /// i's nearest ancestor on it and pushes the rest, found through dof_parentid (each dof is
    /// pushed once a walk). None where the tree is deeper than DEPTH there.
    #[inline(always)]
    pub fn prev(&mut self, i: usize, parent: &[i32]) -> Option<&[u32]> {
        // climb to the path, popping what is not on the way; then write the climb downwards
        let mut n = 0;
        let mut x = i as i32;
        loop {
            while self.len > 0 && self.path[self.len - 1] as i32 > x {
                self.len -= 1;
            }
            if x < 0 || (self.len > 0 && self.path[self.len - 1] as i32 == x) {
                break;
            }
            n += 1;
            if self.len + n > DEPTH {
                self.len = 0;
                return None;
            }
            x = parent[x as usize];
        }
        let mut x = i as u32;
        for k in (self.len..self.len + n).rev() {
            self.path[k] = x;
            x = parent[x as usize] as u32;
        }
        self.len += n;
        Some(&self.path[..self.len - 1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ancestors(parent: &[i32], i: usize) -> Vec<u32> {
        let mut a = Vec::new();
        let mut j = parent[i];
        while j >= 0 {
            a.push(j as u32);
            j = parent[j as usize];
        }
        a.reverse();
        a
    }

    #[test]
    fn path_gives_the_ancestors_or_nothing() {
        // two trees, branches, a chain deeper than DEPTH, and a dof out of depth-first order
        let mut parent = vec![-1, 0, 1, 1, 3, 0, -1, 6];
        let deep = parent.len();
        parent.push(-1);
        for k in 1..DEPTH + 5 {
            parent.push((deep + k - 1) as i32);
        }
        parent.push(deep as i32 + 2);
        parent.push(2);
        parent.push(-1);
        parent.push(parent.len() as i32 - 1);
        let mut path = DofPath::new();
        let mut known = 0;
        for (i, &p) in parent.iter().enumerate() {
            match path.next(i, p) {
                Some(a) => {
                    assert_eq!(a, &ancestors(&parent, i)[..], "dof {i}");
                    known += 1;
                }
                None => assert!(ancestors(&parent, i).len() >= DEPTH || i >= deep + DEPTH),
            }
        }
        assert_eq!(known, parent.len() - 7);
        let mut rev = DofPath::new();
        let mut known = 0;
        for i in (0..parent.len()).rev() {
            match rev.prev(i, &parent) {
                Some(a) => {
                    assert_eq!(a, &ancestors(&parent, i)[..], "dof {i}");
                    known += 1;
                }
                None => assert!(ancestors(&parent, i).len() >= DEPTH),
            }
        }
        assert_eq!(known, parent.len() - 5);
    }
}
