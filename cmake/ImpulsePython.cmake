# IMPULSE_PYTHON: a python3 that can `import google.protobuf` (Debian's
# python3-protobuf), for the protocol page's check and the Python example.
# The system interpreter is tried first: a python3 earlier on PATH (pyenv,
# a virtualenv) usually lacks Debian's packages. Empty when there is none.
if(NOT DEFINED IMPULSE_PYTHON)
  set(_impulse_python "")
  foreach(_candidate /usr/bin/python3 python3)
    find_program(_impulse_python_path NAMES ${_candidate} NO_CACHE)
    if(_impulse_python_path)
      execute_process(COMMAND ${_impulse_python_path} -c "import google.protobuf"
                      RESULT_VARIABLE _impulse_python_missing OUTPUT_QUIET ERROR_QUIET)
      if(_impulse_python_missing EQUAL 0)
        set(_impulse_python ${_impulse_python_path})
        break()
      endif()
    endif()
    unset(_impulse_python_path)
  endforeach()
  set(IMPULSE_PYTHON "${_impulse_python}" CACHE FILEPATH "python3 with google.protobuf (python3-protobuf)")
  if(NOT IMPULSE_PYTHON)
    message(WARNING "No python3 with google.protobuf (apt-get install python3-protobuf): "
                    "the protocol page check and the Python example are not tested")
  endif()
endif()
