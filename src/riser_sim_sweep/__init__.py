"""riser_sim_sweep: load-case sweeps and the speed-accuracy tune of a scene, through riser_sim_cli on Dask.

Modules (one concept each): sweep_file (the sweep file and its checks), case_list (cases from grid, list and
scatter table), scatter_table, keep (what a case keeps from its run), cli_locate, case_run (one CLI run on a
worker), results_folder (table, per-case files, resume), dask_runner (the cluster and the run loop),
progress, plots, tune, main (the command line).
"""
