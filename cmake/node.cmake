# riser_sim_node (see src/node)
