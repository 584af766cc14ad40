//! The built-in UI themes: two spacings (tight, wide) and four color schemes (default, orange,
//! white, black), with 2.2.2's values.

use crate::abi::{mjuiThemeColor, mjuiThemeSpacing};

/// Spacing `ind`: 0 tight, anything else wide.
pub fn spacing(ind: i32) -> mjuiThemeSpacing {
    let v: [i32; 11] = if ind == 0 {
        [270, 15, 100, 8, 4, 4, 4, 8, 4, 30, 4]
    } else {
        [310, 15, 120, 10, 7, 7, 7, 10, 5, 30, 4]
    };
    mjuiThemeSpacing {
        total: v[0],
        scroll: v[1],
        label: v[2],
        section: v[3],
        itemside: v[4],
        itemmid: v[5],
        itemver: v[6],
        texthor: v[7],
        textver: v[8],
        linescroll: v[9],
        samples: v[10],
    }
}

/// Written as doubles, as C writes the literals, and rounded to float on use.
type Rgb = [f64; 3];

/// The 21 colors of a scheme, in mjuiThemeColor's field order.
const SCHEMES: [[Rgb; 21]; 4] = [
    // default
    [
        [0.25, 0.25, 0.25],
        [0.12, 0.12, 0.12],
        [0.6, 0.2, 0.2],
        [1.0, 1.0, 1.0],
        [0.7, 0.7, 0.7],
        [0.1, 0.1, 0.1],
        [0.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.5, 0.5, 0.5],
        [0.3, 0.3, 0.3],
        [0.4, 0.4, 0.4],
        [0.6, 0.4, 0.4],
        [0.4, 0.4, 0.7],
        [0.4, 0.6, 0.4],
        [0.4, 0.6, 0.6],
        [0.2, 0.3, 0.3],
        [0.3, 0.2, 0.3],
        [0.6, 0.4, 0.6],
        [0.6, 0.6, 0.4],
        [0.7, 0.0, 0.0],
        [0.9, 0.9, 0.9],
    ],
    // orange
    [
        [0.2, 0.2, 0.2],
        [0.12, 0.12, 0.12],
        [0.3, 0.3, 0.3],
        [0.8, 0.8, 0.8],
        [0.7, 0.7, 0.7],
        [0.15, 0.15, 0.15],
        [0.0, 0.0, 1.0],
        [0.9, 0.9, 0.9],
        [0.5, 0.5, 0.5],
        [0.2, 0.2, 0.2],
        [0.25, 0.25, 0.25],
        [0.6, 0.4, 0.2],
        [0.6, 0.4, 0.2],
        [0.6, 0.4, 0.2],
        [0.6, 0.4, 0.2],
        [0.3, 0.2, 0.1],
        [0.2, 0.2, 0.2],
        [0.6, 0.4, 0.2],
        [0.6, 0.4, 0.2],
        [0.7, 0.0, 0.0],
        [0.9, 0.9, 0.9],
    ],
    // white
    [
        [0.9, 0.9, 0.9],
        [0.7, 0.7, 0.7],
        [0.8, 0.8, 0.8],
        [0.0, 0.0, 0.8],
        [0.0, 0.0, 0.8],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
        [0.0, 0.0, 0.0],
        [0.7, 0.7, 0.7],
        [0.95, 0.95, 0.95],
        [0.9, 0.9, 0.9],
        [0.8, 0.8, 0.8],
        [0.8, 0.8, 0.8],
        [0.8, 0.8, 0.8],
        [0.8, 0.8, 0.8],
        [0.9, 0.9, 0.9],
        [0.95, 0.95, 0.95],
        [0.8, 0.8, 0.8],
        [0.8, 0.8, 0.8],
        [1.0, 0.3, 0.3],
        [0.2, 0.2, 0.2],
    ],
    // black
    [
        [0.15, 0.15, 0.15],
        [0.3, 0.3, 0.3],
        [0.25, 0.25, 0.25],
        [1.0, 0.3, 0.3],
        [1.0, 0.3, 0.3],
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.4, 0.4, 0.4],
        [0.1, 0.1, 0.1],
        [0.15, 0.15, 0.15],
        [0.3, 0.3, 0.3],
        [0.3, 0.3, 0.3],
        [0.3, 0.3, 0.3],
        [0.3, 0.3, 0.3],
        [0.15, 0.15, 0.15],
        [0.15, 0.15, 0.15],
        [0.3, 0.3, 0.3],
        [0.3, 0.3, 0.3],
        [0.8, 0.2, 0.2],
        [0.8, 0.8, 0.8],
    ],
];

/// Color scheme `ind`: 0 default, 1 orange, 2 white, anything else black.
pub fn color(ind: i32) -> mjuiThemeColor {
    let s = &SCHEMES[match ind {
        0 => 0,
        1 => 1,
        2 => 2,
        _ => 3,
    }];
    let c = s.map(|v| v.map(|x| x as f32));
    mjuiThemeColor {
        master: c[0],
        thumb: c[1],
        secttitle: c[2],
        sectfont: c[3],
        sectsymbol: c[4],
        sectpane: c[5],
        shortcut: c[6],
        fontactive: c[7],
        fontinactive: c[8],
        decorinactive: c[9],
        decorinactive2: c[10],
        button: c[11],
        check: c[12],
        radio: c[13],
        select: c[14],
        select2: c[15],
        slider: c[16],
        slider2: c[17],
        edit: c[18],
        edit2: c[19],
        cursor: c[20],
    }
}
