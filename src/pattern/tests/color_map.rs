//! Colour maps and layering: interpolation between stops, the ends, sharp edges, stop lookup,
//! and `Rgbft::over` by its definition (covered share, filtered share, transmitted share).

use glam::DVec3;

use crate::pattern::{ColorMap, Rgbft, Stop};

fn stop(at: f64, rgb: DVec3) -> Stop {
    Stop {
        at,
        color: Rgbft::opaque(rgb),
    }
}

#[test]
fn values_between_stops_interpolate_and_the_ends_hold() {
    let map = ColorMap::new(vec![stop(0.8, DVec3::Z), stop(0.2, DVec3::X)]).unwrap();
    assert_eq!(map.stops()[0].at, 0.2, "sorted");
    assert_eq!(map.at(-3.0).rgb, DVec3::X);
    assert_eq!(map.at(0.2).rgb, DVec3::X);
    assert!(
        (map.at(0.5).rgb - DVec3::new(0.5, 0.0, 0.5))
            .abs()
            .max_element()
            < 1e-15
    );
    assert_eq!(map.at(0.8).rgb, DVec3::Z);
    assert_eq!(map.at(7.0).rgb, DVec3::Z);
}

#[test]
fn two_stops_at_one_place_make_a_sharp_edge_in_written_order() {
    let map = ColorMap::new(vec![
        stop(0.0, DVec3::X),
        stop(0.5, DVec3::X),
        stop(0.5, DVec3::Z),
        stop(1.0, DVec3::Z),
    ])
    .unwrap();
    assert_eq!(map.at(0.5 - 1e-12).rgb, DVec3::X);
    assert_eq!(map.at(0.5).rgb, DVec3::Z);
    assert_eq!(map.stop_index(0.49), 0);
    assert_eq!(map.stop_index(0.5), 2);
    assert_eq!(map.stop_index(-1.0), 0);
}

#[test]
fn filter_and_transmit_interpolate_too() {
    let clear = Stop {
        at: 1.0,
        color: Rgbft {
            rgb: DVec3::ONE,
            filter: 0.4,
            transmit: 1.0,
        },
    };
    let map = ColorMap::new(vec![stop(0.0, DVec3::ZERO), clear]).unwrap();
    let mid = map.at(0.25);
    assert_eq!((mid.filter, mid.transmit), (0.1, 0.25));
}

#[test]
fn an_empty_or_non_finite_map_is_refused() {
    assert!(ColorMap::new(Vec::new()).is_none());
    assert!(ColorMap::new(vec![stop(f64::NAN, DVec3::ONE)]).is_none());
}

#[test]
fn entries_give_tile_i_colour_i() {
    let map = ColorMap::entries(&[DVec3::X, DVec3::Y, DVec3::Z]).unwrap();
    for (i, c) in [DVec3::X, DVec3::Y, DVec3::Z].iter().enumerate() {
        assert_eq!(map.at(i as f64).rgb, *c);
    }
}

#[test]
fn a_layer_covers_filters_and_transmits_by_its_shares() {
    let below = Rgbft::opaque(DVec3::new(0.2, 0.4, 0.6));
    let top = |filter: f64, transmit: f64| Rgbft {
        rgb: DVec3::new(1.0, 0.5, 0.0),
        filter,
        transmit,
    };
    assert_eq!(top(0.0, 0.0).over(below).rgb, DVec3::new(1.0, 0.5, 0.0));
    assert_eq!(top(0.0, 1.0).over(below).rgb, below.rgb);
    assert_eq!(top(1.0, 0.0).over(below).rgb, DVec3::new(0.2, 0.2, 0.0));
    let mixed = top(0.25, 0.25).over(below).rgb;
    let want =
        0.5 * DVec3::new(1.0, 0.5, 0.0) + 0.25 * DVec3::new(0.2, 0.2, 0.0) + 0.25 * below.rgb;
    assert!((mixed - want).abs().max_element() < 1e-15);
    assert!((top(0.3, 0.2).coverage() - 0.5).abs() < 1e-15);
}
