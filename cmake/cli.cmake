# riser_sim_cli (see src/cli)
