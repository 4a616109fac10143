//! The hostile cases, as data: `name => Case::new(ARGS, EXPECT)` with input, environment,
//! bound, setup and check. Each becomes its own `#[test]`; the shared runner is
//! [`super::runner::run_case`]. No expected value here is copied from qmckit's output:
//! checks are properties (finite values, well-formed SVG, a file left as the user wrote it,
//! an option echoed as given, padding equal to an earlier dimension as pbrt-v4 defines it).

use super::checks::*;
use super::runner::{Case, Expect, Input, run_case};

use Expect::{Answer, AnswerOrRefuse, Fail, Refuse};

// ---------------------------------------------------------------------------------------
// The table.

macro_rules! cases {
    ($($name:ident => $case:expr;)*) => {
        $(
            #[test]
            fn $name() {
                if let Err(e) = run_case(stringify!($name), $case) {
                    panic!("{}: {:?}: {e}", stringify!($name), ($case).args);
                }
            }
        )*

        /// Every case with its name.
        fn table() -> Vec<(&'static str, Case)> {
            vec![$((stringify!($name), $case)),*]
        }
    };
}

cases! {
    // --- panics and aborts -------------------------------------------------------------
    panic_plot_spectrum_frequency_2_62 => Case::new(&["plot", "--out", "out.svg"], Refuse)
        .stdin("# kx ky power\n4611686018427387904 0 1\n")
        .check(svg_written);
    panic_plot_spectrum_frequency_negative => Case::new(
        &["plot", "--kind", "spectrum", "--out", "out.png"], Refuse)
        .stdin("-9.3e18 0 1\n0 0 1\n")
        .check(png_written);
    panic_plot_spectrum_fuzzed_frequencies => Case::new(
        &["plot", "--kind", "spectrum", "--out", "out.svg"], Refuse)
        .stdin("5179970051  0517 7\r01 0 000")
        .check(svg_written);
    panic_plot_spectrum_one_cell => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# kx ky power\n0 0 1\n")
        .check(svg_written);
    panic_plot_radial_no_rows_but_labels => Case::new(
        &["plot", "--kind", "radial", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# label: a\n#\n# label: b\n1 1 1e308 1\n2 1 -1e308 1\n")
        .check(svg_written);
    panic_discrepancy_npy_claims_4g => Case::new(&["discrepancy"], Refuse)
        .stdin(npy_claims_4g());
    panic_discrepancy_npy_file_claims_4g => Case::new(&["discrepancy", "big.npy"], Refuse)
        .setup(big_npy_file);
    panic_spectrum_npy_claims_4g => Case::new(&["spectrum"], Refuse)
        .stdin(npy_claims_4g_2d());
    panic_pcf_npy_claims_4g => Case::new(&["pcf"], Refuse).stdin(npy_claims_4g_2d());
    panic_pcf_npy_dims_2_62 => Case::new(&["pcf"], Refuse)
        .stdin(npy("<f8", "(1, 4611686018427387904)", &[0; 16]));
    panic_discrepancy_npy_shape_overflow => Case::new(&["discrepancy"], Refuse)
        .stdin(npy("<f8", "(4294967296, 4294967296)", &[0; 16]));
    panic_discrepancy_npy_big_endian_nan => Case::new(&["discrepancy"], Refuse)
        .stdin(npy("<f8", "(2, 1)", &[0xff; 16]));
    panic_variance_sets_2_29 => Case::new(
        &["variance", "halton", "-n", "1", "--sets", "536870912"], AnswerOrRefuse)
        .within(budget(10.0));
    panic_variance_sets_max_poisson => Case::new(
        &["variance", "poisson", "-n", "4294967295", "--sets", "4294967295"], Refuse);
    panic_discrepancy_gigabyte_of_zeros => Case::new(&["discrepancy"], AnswerOrRefuse)
        .input(Input::Repeat(b"0\n", 1 << 29))
        .within(10.0);
    panic_points_csv_line_of_2_27 => Case::new(
        &["points", "independent", "-n", "1", "-d", "134217728", "--format", "csv"],
        AnswerOrRefuse);
    panic_points_npy_line_of_2_27 => Case::new(
        &["points", "independent", "-n", "2", "-d", "134217728", "--format", "npy"],
        AnswerOrRefuse);
    panic_rayon_4000_threads => Case::new(&["discrepancy", "--metric", "star"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "4000")]);
    panic_rayon_threads_not_a_number => Case::new(&["spectrum", "--k-max", "4"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "-1")]);
    panic_rayon_threads_max => Case::new(&["pcf", "--bins", "8"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "18446744073709551615")]);
    panic_points_stratified_dims_max => Case::new(
        &["points", "stratified", "-n", "1", "-d", "18446744073709551615"], Refuse);
    panic_points_stratified_dims_64 => Case::new(
        &["points", "stratified", "-n", "2", "-d", "64"], AnswerOrRefuse);
    panic_points_faure_dims_max => Case::new(
        &["points", "faure", "-n", "1", "-d", "4294967295"], Refuse);
    panic_points_kronecker_dims_2_27 => Case::new(
        &["points", "kronecker", "-n", "1", "-d", "134217728"], AnswerOrRefuse);
    panic_pixel_zsobol_spp_2_31 => Case::new(
        &["pixel", "zsobol", "--resolution", "4294967295x4294967295", "--spp", "2147483648",
          "--pixel", "4294967294,4294967294"], AnswerOrRefuse);
    panic_pixel_pmj02bn_spp_max => Case::new(
        &["pixel", "pmj02bn", "--resolution", "1x1", "--spp", "4294967295", "--pixel", "0,0"],
        AnswerOrRefuse);
    panic_pixel_padded_sobol_far_pixel => Case::new(
        &["pixel", "padded-sobol", "--resolution", "4294967295x1", "--spp", "4",
          "--pixel", "4294967294,0", "--dim", "4294967295"], AnswerOrRefuse);
    panic_tvalue_faure_base_past_u16 => Case::new(
        &["tvalue", "faure", "-m", "2", "-d", "2", "--base", "4294967291"], Refuse);
    panic_tvalue_sobol_dims_past_table => Case::new(
        &["tvalue", "sobol", "-m", "4", "-d", "21202"], Refuse);
    panic_convergence_stratified_dims_64 => Case::new(
        &["convergence", "stratified", "-d", "64", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    panic_convergence_seeds_max => Case::new(
        &["convergence", "sobol", "--scramble", "owen", "--seeds", "18446744073709551615"],
        Refuse);
    panic_mask_size_overflow => Case::new(
        &["mask", "void-and-cluster", "--size", "4294967296x4294967296"], Refuse);
    panic_mask_sigma_subnormal => Case::new(
        &["mask", "void-and-cluster", "--size", "8x8", "--sigma", "5e-324"], Refuse);
    panic_report_png_budget_zero => Case::new(
        &["report", "--quick", "--png", "--out", "r", "--max-seconds", "1e-300"], Refuse);

    // --- hangs -------------------------------------------------------------------------
    hang_plot_convergence_span_1e308_1e_308 => Case::new(&["plot", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("# n rmse\n1 1e308\n2 1e-308\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_convergence_subnormal => Case::new(&["plot", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("# n rmse\n1 0.5\n2 5e-324\n4 0.25\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_convergence_n_span => Case::new(&["plot", "--out", "out.png"], AnswerOrRefuse)
        .stdin("# n rmse\n1e-300 1\n1e300 2\n")
        .within(SMALL_FIGURE)
        .check(png_written);
    hang_plot_radial_span => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# radius count mean anisotropy\n1 4 1e308 1\n2 4 4.9e-324 1\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_image_colour_span_inf => Case::new(
        &["plot", "--kind", "image", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("-1.7e308 1.7e308\n0 1\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_image_diverging_span_inf => Case::new(
        &["plot", "--kind", "image", "--colours", "diverging", "--out", "out.png"],
        AnswerOrRefuse)
        .stdin("-1.7e308 1.7e308\n1e-320 0\n")
        .within(SMALL_FIGURE)
        .check(png_written);
    hang_plot_spectrum_power_span => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin(
            "# kx ky power\n-1 -1 1e308\n0 -1 5e-324\n1 -1 0\n-1 0 1\n0 0 1e-308\n1 0 1\n\
             -1 1 1\n0 1 1\n1 1 1e300\n",
        )
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_points_on_the_boundary => Case::new(
        &["plot", "--intervals", "4096x4096", "--groups", "1", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("1 1\n0 0\n1 0\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_pcf_sigma_huge => Case::new(&["pcf", "--sigma", "1e308"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    hang_spectrum_tolerance_tiny => Case::new(
        &["spectrum", "--tolerance", "5e-324", "--k-max", "2048", "--max-seconds", "1"],
        AnswerOrRefuse)
        .stdin(few_points())
        .within(budget(1.0));
    hang_discrepancy_delta_tiny => Case::new(
        &["discrepancy", "--metric", "star-bounds", "--delta", "5e-324",
          "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(few_points())
        .within(budget(1.0));
    hang_tvalue_faure_many_dims => Case::new(
        &["tvalue", "faure", "-m", "32", "-d", "1000", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    hang_variance_gaussian_sigma_subnormal => Case::new(
        &["variance", "sobol", "-n", "16", "--integrand", "gaussian", "--sigma", "5e-324",
          "--sets", "4"], AnswerOrRefuse);

    // --- the budget bounds the run -----------------------------------------------------
    budget_mask_void_and_cluster_1540 => Case::new(
        &["mask", "void-and-cluster", "--size", "1540x1540", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0))
        .check(rectangular);
    budget_mask_void_and_cluster_4096 => Case::new(
        &["mask", "void-and-cluster", "--size", "4096x1024", "--max-seconds", "2",
          "--format", "png"], AnswerOrRefuse)
        .within(budget(2.0));
    budget_points_poisson_maximal_7d => Case::new(
        &["points", "poisson", "--radius", "1", "-d", "7", "--torus", "--maximal",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_poisson_maximal_8d_small_radius => Case::new(
        &["points", "poisson", "--radius", "0.3", "-d", "8", "--maximal",
          "--max-seconds", "2"], AnswerOrRefuse)
        .within(budget(2.0));
    budget_points_poisson_n_11256250 => Case::new(
        &["points", "poisson", "-n", "11256250", "-d", "1", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_gaussian_blue_noise => Case::new(
        &["points", "gaussian-blue-noise", "-n", "4096", "--iterations", "4294967295",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_best_candidate => Case::new(
        &["points", "best-candidate", "-n", "100000", "--candidates", "4294967295",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_pmj02bn => Case::new(
        &["points", "pmj02bn", "-n", "4194304", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_discrepancy_star_3d => Case::new(
        &["discrepancy", "--metric", "star", "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(random_points(20000, 3, 2))
        .within(budget(1.0));
    budget_discrepancy_all_20d => Case::new(
        &["discrepancy", "--metric", "all", "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(random_points(4000, 20, 3))
        .within(budget(1.0));
    budget_spectrum_direct => Case::new(
        &["spectrum", "--method", "direct", "--k-max", "256", "--max-seconds", "1"],
        AnswerOrRefuse)
        .stdin(random_points(20000, 2, 4))
        .within(budget(1.0));
    budget_pcf_many_points => Case::new(&["pcf", "--max-seconds", "1", "--r-max", "0.5"],
        AnswerOrRefuse)
        .stdin(random_points(40000, 2, 5))
        .within(budget(1.0));
    budget_tvalue_counted => Case::new(
        &["tvalue", "sobol", "-m", "21", "-d", "3", "--scramble", "owen",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_convergence_owen_halton => Case::new(
        &["convergence", "halton", "-d", "16", "--scramble", "owen", "--max-m", "20",
          "--seeds", "2", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_convergence_poisson => Case::new(
        &["convergence", "poisson", "--max-m", "16", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_variance_poisson => Case::new(
        &["variance", "poisson", "-n", "4096", "--sets", "64", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_variance_halton_many_sets => Case::new(
        &["variance", "halton", "-n", "1", "--sets", "536870912", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_report_quick => Case::new(
        &["report", "--quick", "--out", "r", "--max-seconds", "2"], AnswerOrRefuse)
        .within(budget(2.0) + 2.0);

    // --- unbounded reads ---------------------------------------------------------------
    read_points_lattice_vector_dev_zero => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "/dev/zero"], Refuse)
        .within(READ_REFUSAL);
    read_points_lattice_vector_sparse => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "sparse"], Refuse)
        .setup(lattice_files)
        .within(READ_REFUSAL);
    read_points_lattice_vector_huge_header => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "huge.lattice"], Refuse)
        .setup(lattice_files);
    read_discrepancy_stdin_dev_zero => Case::new(&["discrepancy"], Refuse)
        .input(Input::File("/dev/zero"))
        .within(READ_REFUSAL);
    read_discrepancy_file_dev_zero => Case::new(&["discrepancy", "/dev/zero"], Refuse)
        .within(READ_REFUSAL);
    read_discrepancy_sparse_2g => Case::new(&["discrepancy", "sparse"], Refuse)
        .setup(sparse_2g)
        .within(READ_REFUSAL);
    read_spectrum_sparse_2g_stdin => Case::new(&["spectrum"], Refuse)
        .setup(sparse_2g)
        .input(Input::File("sparse"))
        .within(READ_REFUSAL);
    read_pcf_dev_urandom => Case::new(&["pcf", "/dev/urandom"], Refuse)
        .within(READ_REFUSAL);
    read_plot_dev_zero => Case::new(&["plot", "--out", "out.svg"], Refuse)
        .input(Input::File("/dev/zero"))
        .within(READ_REFUSAL)
        .check(svg_written);
    read_plot_image_sparse_2g => Case::new(
        &["plot", "--kind", "image", "--out", "out.png", "sparse"], Refuse)
        .setup(sparse_2g)
        .within(READ_REFUSAL)
        .check(png_written);
    read_plot_endless_pgm_header => Case::new(&["plot", "--out", "out.png"], Refuse)
        .input(Input::Repeat(b"P5 ", 1 << 28))
        .within(5.0)
        .check(png_written);
    read_discrepancy_endless_comment => Case::new(&["discrepancy"], Refuse)
        .input(Input::Repeat(b"################", 1 << 27))
        .within(5.0);

    // --- data loss ---------------------------------------------------------------------
    loss_report_out_empty => Case::new(&["report", "--quick", "--out", ""], Refuse);
    loss_report_keeps_user_index => Case::new(
        &["report", "--quick", "--out", "site", "--max-seconds", "2"], AnswerOrRefuse)
        .setup(user_site)
        .within(budget(2.0) + 2.0)
        .check(user_site_kept);
    loss_plot_read_only_dir => Case::new(
        &["plot", "--out", "ro/fig.svg", "pts.txt"], Fail)
        .setup(read_only_figure)
        .unprivileged()
        .check(read_only_figure_kept);
    loss_plot_refused_input_keeps_figure => Case::new(
        &["plot", "--out", "fig.svg", "--kind", "spectrum", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);
    loss_plot_out_is_a_directory => Case::new(&["plot", "--out", "ro.svg", "pts.txt"], Fail)
        .setup(|dir| {
            earlier_figure(dir, "ro.svg");
        })
        .check(|run| earlier_figure_kept(run, "ro.svg"));
    loss_plot_out_empty => Case::new(&["plot", "--out", "", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);
    loss_plot_out_has_no_extension => Case::new(&["plot", "--out", "fig", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);

    // --- wrong answers presented as answers --------------------------------------------
    wrong_pcf_sigma_5e_324 => Case::new(&["pcf", "--sigma", "5e-324"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    wrong_pcf_sigma_nan => Case::new(&["pcf", "--sigma", "nan"], Refuse).stdin(few_points());
    wrong_pcf_r_max_subnormal => Case::new(&["pcf", "--r-max", "5e-324"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    wrong_variance_radius_1e_200 => Case::new(
        &["variance", "sobol", "-n", "16", "--radius", "1e-200", "--sets", "8"],
        AnswerOrRefuse)
        .check(radius_honoured);
    wrong_variance_k_max_0 => Case::new(
        &["variance", "sobol", "-n", "16", "--k-max", "0", "--sets", "8"], AnswerOrRefuse)
        .check(k_max_honoured);
    wrong_variance_radius_nan => Case::new(
        &["variance", "sobol", "-n", "16", "--radius", "nan"], Refuse);
    wrong_plot_title_control_character => Case::new(
        &["plot", "--title", "a\u{1}b\u{1b}[31m <&> ]]> \"q\" \u{fffe}", "--out", "out.svg"],
        Answer)
        .stdin(few_points())
        .check(svg_written);
    wrong_plot_title_control_character_image => Case::new(
        &["plot", "--kind", "image", "--title", "\u{7}\u{8}\r\n\t&amp", "--out", "out.svg"],
        Answer)
        .stdin("0 1\n2 3\n")
        .check(svg_written);
    wrong_plot_curve_label_control_character => Case::new(
        &["plot", "--out", "out.svg"], Answer)
        .stdin("# n rmse\n# label: x\u{2}y<z&\n1 0.5\n2 0.25\n4 0.125\n")
        .check(svg_written);
    wrong_npy_header_syntax_error_is_one_line => Case::new(&["discrepancy"], Refuse)
        .stdin(&b"\x93NUMPY\x01\x00\x04\x00{x}\n"[..]);
    wrong_npy_header_of_python_code_is_one_line => Case::new(&["spectrum"], Refuse)
        .stdin(npy("<f8", "__import__('os')", &[0; 16]));
    wrong_spectrum_tolerance_nan => Case::new(&["spectrum", "--tolerance", "nan"], Refuse)
        .stdin(few_points());
    wrong_discrepancy_delta_nan => Case::new(
        &["discrepancy", "--metric", "star-bounds", "--delta", "nan"], Refuse)
        .stdin(few_points());
    wrong_discrepancy_coordinate_past_one => Case::new(&["discrepancy"], Refuse)
        .stdin("0.5 1.0000000000000002\n");
    wrong_points_u32_coordinate_2_32 => Case::new(&["discrepancy", "--input-format", "u32"],
        Refuse)
        .stdin("4294967296 0\n");
    wrong_tvalue_m_past_32 => Case::new(&["tvalue", "sobol", "-m", "33"], Refuse);
    wrong_convergence_max_m_past_24 => Case::new(
        &["convergence", "sobol", "--max-m", "25"], Refuse);
    wrong_mask_sigma_nan => Case::new(
        &["mask", "void-and-cluster", "--size", "8x8", "--sigma", "nan"], Refuse);
    wrong_pixel_outside_the_image => Case::new(
        &["pixel", "independent", "--resolution", "4x4", "--spp", "4", "--pixel", "4,0"],
        Refuse);
    wrong_pixel_zsobol_spp_not_power_of_two => Case::new(
        &["pixel", "zsobol", "--resolution", "4x4", "--spp", "3", "--pixel", "0,0"], Refuse);
    wrong_report_budget_nan => Case::new(
        &["report", "--quick", "--out", "r", "--max-seconds", "nan"], Refuse);

    // --- listed but broken -------------------------------------------------------------
    listed_convergence_poisson => Case::new(&["convergence", "poisson"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_gaussian_blue_noise => Case::new(
        &["convergence", "gaussian-blue-noise"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_best_candidate => Case::new(&["convergence", "best-candidate"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_pmj02bn => Case::new(&["convergence", "pmj02bn"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_pixel_sobol_pads_like_pbrt => Case::new(
        &["pixel", "sobol", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "4294967295"], Answer)
        .check(|run| eight_lines(run).and_then(|()| sobol_pads_like_pbrt(run)));
    listed_pixel_every_sampler_past_dims => Case::new(
        &["pixel", "padded-sobol", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "21201"], Answer)
        .check(eight_lines);
    listed_pixel_pmj02_past_dims => Case::new(
        &["pixel", "pmj02", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "4294967295"], Answer)
        .check(eight_lines);
    listed_tvalue_every_base2_sampler => Case::new(&["tvalue", "lp", "-m", "32"], Answer);
    listed_spectrum_radial_of_one_point => Case::new(
        &["spectrum", "--radial", "--k-max", "1"], Answer)
        .stdin("0.5 0.5\n");
    listed_pcf_torus_of_two_points => Case::new(&["pcf", "--torus", "--r-max", "0.5"], Answer)
        .stdin("0.1 0.1\n0.6 0.6\n")
        .check(pcf_rows);
    listed_discrepancy_npy_of_float32 => Case::new(&["discrepancy", "--metric", "star"], Answer)
        .stdin(npy("<f4", "(2, 2)", &[0, 0, 0, 0x3f, 0, 0, 0x80, 0x3e, 0, 0, 0x40, 0x3f, 0, 0, 0, 0]));
    listed_mask_one_pixel => Case::new(&["mask", "void-and-cluster", "--size", "1x1"],
        AnswerOrRefuse);
    listed_variance_every_sampler => Case::new(
        &["variance", "gaussian-blue-noise", "-n", "64", "--sets", "2"], Answer);
    listed_plot_points_of_own_output => Case::new(&["plot", "--out", "out.svg"], Answer)
        .stdin(random_points(16, 3, 6))
        .check(svg_written);
    listed_report_help => Case::new(&["report", "--help"], Answer);
}

/// The commands of `qmckit --help`, and the classes of the module docs.
const COMMANDS: [&str; 11] = [
    "points",
    "pixel",
    "discrepancy",
    "tvalue",
    "convergence",
    "spectrum",
    "pcf",
    "variance",
    "mask",
    "plot",
    "report",
];
const CLASSES: [&str; 7] = [
    "panic_", "hang_", "budget_", "read_", "loss_", "wrong_", "listed_",
];

#[test]
fn covers_every_class_and_command() {
    let table = table();
    for class in CLASSES {
        assert!(
            table.iter().any(|(n, _)| n.starts_with(class)),
            "no {class} case"
        );
    }
    for command in COMMANDS {
        assert!(
            table.iter().any(|(_, c)| c.args.first() == Some(&command)),
            "no case for {command}"
        );
    }
    for (name, _) in &table {
        assert!(
            CLASSES.iter().any(|c| name.starts_with(c)),
            "{name}: no class"
        );
    }
    // Every class reaches most commands: the cross table is printed for the record.
    for class in CLASSES {
        let hit: Vec<&str> = COMMANDS
            .iter()
            .copied()
            .filter(|cmd| {
                table
                    .iter()
                    .any(|(n, c)| n.starts_with(class) && c.args.first() == Some(cmd))
            })
            .collect();
        eprintln!("{class:8} {hit:?}");
    }
}
