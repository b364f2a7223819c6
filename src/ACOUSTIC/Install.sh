# Install/uninstall the ACOUSTIC package in a LAMMPS source tree for the
# traditional make build:   cd src && make yes-acoustic && make mpi
# mode = 0/1/2 for uninstall/install/update
mode=$1

# enforce using portable C locale
LC_ALL=C
export LC_ALL

# arg1 = file, arg2 = file it depends on
action () {
  if (test $mode = 0) then
    rm -f ../$1
  elif (! cmp -s $1 ../$1) then
    if (test -z "$2" || test -e ../$2) then
      cp $1 ..
      if (test $mode = 2) then
        echo "  updating src/$1"
      fi
    fi
  elif (test -n "$2") then
    if (test ! -e ../$2) then
      rm -f ../$1
    fi
  fi
}

# the package extends the GRANULAR package (its sub-models and pair granular)
if (test $mode = 1) then
  if (test ! -e ../pair_granular.cpp) then
    echo "Must install GRANULAR package with ACOUSTIC: make yes-granular yes-acoustic"
    exit 1
  fi
fi

# every source file of the package (the styles)
for file in *.cpp *.h; do
  test -f ${file} && action $file
done

# the numerics are the library lib/acoustic (build it first, from the top of
# the LAMMPS tree: cd lib/acoustic && make -f Makefile.mpi); its compiler and linker flags for Eigen,
# SuiteSparse and the optional solvers come from lib/acoustic/Makefile.lammps
# (edit it if they are not installed in /usr)
if (test $1 = 1) then
  if (test ! -e ../../lib/acoustic/libacoustic.a) then
    echo "ACOUSTIC: lib/acoustic/libacoustic.a is not built yet: cd lib/acoustic && make -f Makefile.mpi"
  fi
  if (test -e ../Makefile.package) then
    sed -i -e 's/[^ \t]*acoustic[^ \t]* //g' ../Makefile.package
    sed -i -e 's|^PKG_INC =[ \t]*|&-I../../lib/acoustic |' ../Makefile.package
    sed -i -e 's|^PKG_PATH =[ \t]*|&-L../../lib/acoustic |' ../Makefile.package
    sed -i -e 's|^PKG_LIB =[ \t]*|&-lacoustic |' ../Makefile.package
    sed -i -e 's|^PKG_SYSINC =[ \t]*|&$(acoustic_SYSINC) |' ../Makefile.package
    sed -i -e 's|^PKG_SYSLIB =[ \t]*|&$(acoustic_SYSLIB) |' ../Makefile.package
    sed -i -e 's|^PKG_SYSPATH =[ \t]*|&$(acoustic_SYSPATH) |' ../Makefile.package
  fi
  if (test -e ../Makefile.package.settings) then
    sed -i -e '/^include.*acoustic.*$/d' ../Makefile.package.settings
    # multiline form needed for BSD sed on Macs
    sed -i -e '4 i \
include ..\/..\/lib\/acoustic\/Makefile.lammps
' ../Makefile.package.settings
  fi
elif (test $1 = 0) then
  if (test -e ../Makefile.package) then
    sed -i -e 's/[^ \t]*acoustic[^ \t]* //g' ../Makefile.package
  fi
  if (test -e ../Makefile.package.settings) then
    sed -i -e '/^include.*acoustic.*$/d' ../Makefile.package.settings
  fi
fi
