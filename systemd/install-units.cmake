# SPDX-License-Identifier: Apache-2.0
# Runs inside cmake --install (included by systemd/CMakeLists.txt's install(CODE)), where
# CMAKE_INSTALL_PREFIX is the prefix actually installed to. Generates raysd.service with the full
# paths of the binaries and the config, then installs the units, the sysusers.d and tmpfiles.d
# entries, the udev rule and raysd.ini. file(INSTALL) honours DESTDIR and records the files in install_manifest.txt.

# An install directory made absolute for this prefix. The binaries go exactly where
# install(TARGETS) puts them: PREFIX/bin. The config directory follows GNUInstallDirs'
# CMAKE_INSTALL_FULL_SYSCONFDIR rule (GNUInstallDirs_get_absolute_install_dir only runs at
# configure time, so it is repeated here for the prefix installed to): etc is /etc for the
# prefixes / and /usr, /etc/opt/NAME for /opt/NAME, else PREFIX/etc.
function(rays_full_install_dir out dir sysconf_like)
  set(prefix "${CMAKE_INSTALL_PREFIX}")
  if(IS_ABSOLUTE "${dir}")
    set(full "${dir}")
  elseif(sysconf_like AND prefix MATCHES "^(/usr)?/?$")
    set(full "/${dir}")
  elseif(sysconf_like AND prefix MATCHES "^/opt/")
    set(full "/${dir}${prefix}")
  else()
    set(full "${prefix}/${dir}")
  endif()
  string(REGEX REPLACE "//+" "/" full "${full}")
  string(REGEX REPLACE "(.)/$" "\\1" full "${full}")
  set(${out} "${full}" PARENT_SCOPE)
endfunction()

rays_full_install_dir(BINDIR "${RAYS_INSTALL_BINDIR}" FALSE)
rays_full_install_dir(SYSCONFDIR "${RAYS_INSTALL_SYSCONFDIR}" TRUE)
foreach(dir IN ITEMS RAYS_SYSTEMD_UNIT_DIR RAYS_SYSUSERS_DIR RAYS_TMPFILES_DIR RAYS_UDEV_RULES_DIR)
  if(NOT IS_ABSOLUTE "${${dir}}")
    set(${dir} "${CMAKE_INSTALL_PREFIX}/${${dir}}")
  endif()
endforeach()

set(mode FILE_PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
configure_file("${RAYS_UNITS_SOURCE_DIR}/raysd.service.in" "${RAYS_UNITS_BINARY_DIR}/raysd.service" @ONLY)
file(INSTALL "${RAYS_UNITS_BINARY_DIR}/raysd.service" "${RAYS_UNITS_SOURCE_DIR}/raysd.socket"
     DESTINATION "${RAYS_SYSTEMD_UNIT_DIR}" ${mode})
file(INSTALL "${RAYS_UNITS_SOURCE_DIR}/raysd.sysusers" DESTINATION "${RAYS_SYSUSERS_DIR}"
     RENAME raysd.conf ${mode})
file(INSTALL "${RAYS_UNITS_SOURCE_DIR}/raysd.tmpfiles" DESTINATION "${RAYS_TMPFILES_DIR}"
     RENAME raysd.conf ${mode})
file(INSTALL "${RAYS_UNITS_SOURCE_DIR}/raysd-gpio.rules" DESTINATION "${RAYS_UDEV_RULES_DIR}"
     RENAME 60-raysd-gpio.rules ${mode})
file(INSTALL "${RAYS_CONFIG_SOURCE}" DESTINATION "${SYSCONFDIR}/raysd" ${mode})
