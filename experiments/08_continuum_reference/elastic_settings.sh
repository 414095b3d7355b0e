# Sourced by the compare_*.sh scripts: the elastic start of README section 10 with the
# continuum's moduli, strains plastic only (ex1: E 210 GPa, nu 0.3), and the ex3 cup's own
# moduli and the continuum's 1.04 mm holder gap (EX3_SET), as compare_elastic.sh uses them.
# shellcheck disable=SC2034
elastic="material.elastic.law=isotropic material.elastic.E_MPa=210000 material.elastic.nu=0.3 material.elastic.strains=false"
cup="material.elastic.E_MPa=70000 material.elastic.nu=0.33 tool.holder.gap_mm=1.04"
