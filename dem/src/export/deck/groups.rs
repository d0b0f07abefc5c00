//! The deck's atom groups: the five types, and the control layer's halves (by molecule) that
//! carry the mount springs and measure the tilts.

use std::fmt::Write;

/// The groups (types 1 substrate, 2 slider, 3/4 control sub-layers, 5 support; halves).
pub(super) fn groups(s: &mut String) {
    w!(s, "# ---- groups (types: 1 substrate, 2 slider, 3 axial control, 4 lateral control, 5 support) ----");
    w!(s, "group           sub     type 1");
    w!(s, "group           slider  type 2");
    w!(s, "group           ctrl    type 3 4");
    w!(s, "group           ctrla   type 3");
    w!(s, "group           ctrlb   type 4");
    w!(s, "group           support type 5");
    w!(s, "group           mobile  union sub slider");
    w!(s, "group           damped  union sub slider ctrl");
    w!(
        s,
        "# halves of the control layer in the slider's own frame: molecule = 1 + (sx+1) + 3(sy+1),"
    );
    w!(s, "# sx, sy = signs of the site's offset from the disc centre; a site on a dividing line counts");
    w!(
        s,
        "# half to each side (its axial sphere to the + half, its lateral sphere to the - half)."
    );
    w!(s, "group           qxp     molecule 3 6 9");
    w!(s, "group           qxn     molecule 1 4 7");
    w!(s, "group           qx0     molecule 2 5 8");
    w!(s, "group           qyp     molecule 7 8 9");
    w!(s, "group           qyn     molecule 1 2 3");
    w!(s, "group           qy0     molecule 4 5 6");
    w!(s, "group           qx0a    intersect qx0 ctrla");
    w!(s, "group           qx0b    intersect qx0 ctrlb");
    w!(s, "group           qy0a    intersect qy0 ctrla");
    w!(s, "group           qy0b    intersect qy0 ctrlb");
    w!(s, "group           half_xp union qxp qx0a");
    w!(s, "group           half_xn union qxn qx0b");
    w!(s, "group           half_yp union qyp qy0a");
    w!(s, "group           half_yn union qyn qy0b");
    w!(s, "");
}
