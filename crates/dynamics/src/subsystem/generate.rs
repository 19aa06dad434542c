//! Automatic sub-system generation (section 2.9): group bodies with overlapping index sets,
//! close each group under the paths to its common parent, and rewire the body list.

use super::rigid::is_axisymmetric;
use super::{Node, NodeKind, Subsystem, MAX_SUBSYSTEM_DOF};
use crate::model::{Body, BodyId, MAX_INDEX_SET};
use crate::ModelError;

/// Disjoint-set forest over bodies (path halving, union by index).
struct Groups(Vec<usize>);

impl Groups {
    /// Representative of `i`.
    fn find(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }
    /// Joins the groups of `a` and `b`; true if they were different.
    fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        let (lo, hi) = (ra.min(rb), ra.max(rb));
        self.0[hi] = lo;
        true
    }
}

/// Sub-systems and the rewired node list of a body list (steps 1-6 of section 2.9).
///
/// A loop-free model yields no sub-system and one body node per body, in body order.
pub(crate) fn generate(bodies: &[Body]) -> Result<(Vec<Subsystem>, Vec<Node>), ModelError> {
    let n = bodies.len();
    let mut groups = Groups((0..n).collect());
    let mut shared = vec![false; n];
    let mut owner: Vec<Option<BodyId>> = Vec::new();
    for (i, b) in bodies.iter().enumerate() {
        for &v in b.v_set.as_slice() {
            if owner.len() <= v {
                owner.resize(v + 1, None);
            }
            match owner[v] {
                Some(j) => {
                    groups.union(i, j);
                    shared[i] = true;
                    shared[j] = true;
                }
                None => owner[v] = Some(i),
            }
        }
    }
    close_groups(bodies, &mut groups, &mut shared);
    let mut subsystems = Vec::new();
    let mut of_body: Vec<Option<usize>> = vec![None; n];
    for i in 0..n {
        if !shared[i] || groups.find(i) != i {
            continue;
        }
        let members: Vec<BodyId> = (i..n)
            .filter(|&j| shared[j] && groups.find(j) == i)
            .collect();
        for &m in &members {
            of_body[m] = Some(subsystems.len());
        }
        subsystems.push(build_subsystem(bodies, members)?);
    }
    let nodes = node_list(bodies, &subsystems, &of_body);
    Ok((subsystems, nodes))
}

/// Adds to each group the bodies between its members and its common parent (step 2),
/// merging groups that meet, until nothing changes.
fn close_groups(bodies: &[Body], groups: &mut Groups, shared: &mut [bool]) {
    let n = bodies.len();
    let mut changed = true;
    while changed {
        changed = false;
        for i in 0..n {
            if !shared[i] {
                continue;
            }
            let root = groups.find(i);
            let members: Vec<BodyId> = (0..n)
                .filter(|&j| shared[j] && groups.find(j) == root)
                .collect();
            let parent = common_parent(bodies, &members, |j| members.contains(&j));
            for &m in &members {
                let mut k = bodies[m].parent;
                while k != parent {
                    let Some(b) = k else { break };
                    if !shared[b] || groups.find(b) != root {
                        shared[b] = true;
                        groups.union(b, root);
                        changed = true;
                    }
                    k = bodies[b].parent;
                }
            }
        }
    }
}

/// Nearest common ancestor of `members` that is not itself a member (`None` = world).
fn common_parent(
    bodies: &[Body],
    members: &[BodyId],
    is_member: impl Fn(BodyId) -> bool,
) -> Option<BodyId> {
    let path = |mut k: Option<BodyId>| {
        let mut p = Vec::new();
        while let Some(b) = k {
            p.push(b);
            k = bodies[b].parent;
        }
        p
    };
    let mut lca = path(Some(members[0]));
    for &m in &members[1..] {
        let other = path(Some(m));
        lca.retain(|b| other.contains(b));
    }
    lca.into_iter().find(|&b| !is_member(b))
}

/// Sub-system record of one closed group (step 3).
fn build_subsystem(bodies: &[Body], members: Vec<BodyId>) -> Result<Subsystem, ModelError> {
    let is_member = |j: BodyId| members.binary_search(&j).is_ok();
    let parent = common_parent(bodies, &members, is_member);
    let mut v_set: Vec<usize> = members
        .iter()
        .flat_map(|&m| bodies[m].v_set.as_slice().iter().copied())
        .collect();
    v_set.sort_unstable();
    v_set.dedup();
    if v_set.len() > MAX_SUBSYSTEM_DOF {
        return Err(ModelError::SubsystemTooLarge {
            body: bodies[members[0]].name.clone(),
            dof: v_set.len(),
            max: MAX_SUBSYSTEM_DOF,
        });
    }
    let columns = members
        .iter()
        .map(|&m| {
            let mut c = [0; MAX_INDEX_SET];
            for (k, v) in bodies[m].v_set.as_slice().iter().enumerate() {
                c[k] = v_set.binary_search(v).unwrap_or(0);
            }
            c
        })
        .collect();
    let with_outside_children = members
        .iter()
        .copied()
        .filter(|&m| {
            bodies
                .iter()
                .enumerate()
                .any(|(j, b)| b.parent == Some(m) && !is_member(j))
        })
        .collect::<Vec<_>>();
    let rigid_member: Vec<bool> = members
        .iter()
        .map(|m| !with_outside_children.contains(m))
        .collect();
    let axisymmetric_member = members
        .iter()
        .zip(&rigid_member)
        .map(|(&m, &rigid)| {
            let inertia = &bodies[m].inertia;
            rigid && is_axisymmetric(&inertia.com(), &inertia.inertia_about_com())
        })
        .collect();
    Ok(Subsystem {
        members,
        parent,
        v_set,
        columns,
        with_outside_children,
        rigid_member,
        axisymmetric_member,
    })
}

/// Rewired body list (Fig. 2.14): each sub-system at its lowest member's former position,
/// parent links redirected to sub-systems (step 4), children and brothers relinked in list
/// order so that every brother sequence is continuous (the result of Algorithm 2.5, step 5).
fn node_list(bodies: &[Body], subsystems: &[Subsystem], of_body: &[Option<usize>]) -> Vec<Node> {
    let mut node_of_body = vec![0; bodies.len()];
    let mut nodes: Vec<Node> = Vec::with_capacity(bodies.len());
    for i in 0..bodies.len() {
        let kind = match of_body[i] {
            Some(s) if subsystems[s].members[0] == i => NodeKind::Subsystem(s),
            Some(s) => {
                node_of_body[i] = node_of_body[subsystems[s].members[0]];
                continue;
            }
            None => NodeKind::Body(i),
        };
        let parent_body = match kind {
            NodeKind::Body(b) => bodies[b].parent,
            NodeKind::Subsystem(s) => subsystems[s].parent,
        };
        node_of_body[i] = nodes.len();
        nodes.push(Node {
            kind,
            parent: parent_body.map(|p| node_of_body[p]),
            first_child: None,
            brother: None,
        });
    }
    let mut last_child: Vec<Option<usize>> = vec![None; nodes.len()];
    let mut last_root = None;
    for k in 0..nodes.len() {
        let slot = match nodes[k].parent {
            Some(p) => &mut last_child[p],
            None => &mut last_root,
        };
        match *slot {
            Some(prev) => nodes[prev].brother = Some(k),
            None => {
                if let Some(p) = nodes[k].parent {
                    nodes[p].first_child = Some(k);
                }
            }
        }
        *slot = Some(k);
    }
    nodes
}
