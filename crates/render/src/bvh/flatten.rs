//! Depth-first flattening of the build tree, and the tree's SAH cost.

use super::Node;
use super::build::{BuildNode, BuildOptions, leaf_cost};
use crate::math::{Bounds3, Vec3};

/// Appends the subtree depth-first to `nodes`, making child indices absolute.
pub(super) fn flatten(node: &BuildNode, nodes: &mut Vec<Node>) {
    match node {
        BuildNode::Flat(sub) => {
            let base = nodes.len() as u32;
            nodes.extend(sub.iter().map(|n| {
                let mut n = *n;
                if !n.is_leaf() {
                    n.offset += base;
                }
                n
            }));
        }
        BuildNode::Interior {
            bounds,
            axis,
            children,
        } => {
            let idx = nodes.len();
            nodes.push(Node {
                min: bounds.min.to_array(),
                max: bounds.max.to_array(),
                offset: 0,
                count: 0,
                axis: *axis,
                pad: 0,
            });
            flatten(&children[0], nodes);
            nodes[idx].offset = nodes.len() as u32;
            flatten(&children[1], nodes);
        }
    }
}

/// Sum over nodes of `area * cost` for the build's SAH model (see
/// [`BuildOptions`]), divided by the root area.
pub(super) fn sah_cost(nodes: &[Node], opts: BuildOptions) -> f64 {
    let area = |n: &Node| {
        Bounds3 {
            min: Vec3::from_array(n.min),
            max: Vec3::from_array(n.max),
        }
        .surface_area() as f64
    };
    let Some(root) = nodes.first() else {
        return 0.0;
    };
    let ra = area(root);
    if !(ra > 0.0) {
        return 0.0;
    }
    nodes
        .iter()
        .map(|n| {
            area(n)
                * if n.is_leaf() {
                    leaf_cost(n.count as u32) as f64
                } else {
                    opts.traversal_cost as f64
                }
        })
        .sum::<f64>()
        / ra
}
