./run_case.sh ex1_mu000_r60_l4 --case ex1 --friction 0 --radial 60 --layers 4
./run_case.sh ex1_mu030_r60_l4 --case ex1 --friction 0.3 --radial 60 --layers 4
./run_case.sh ex1_mu010_r60_l4_E100x --case ex1 --friction 0.1 --radial 60 --layers 4 --E 21000000
