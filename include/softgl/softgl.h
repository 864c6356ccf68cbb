// softgl/softgl.h — the whole public API: include this one header.
#pragma once

#include <softgl/config.h>

#include <softgl/context.h>
#include <softgl/enums.h>
#include <softgl/image.h>
#include <softgl/shader.h>
#include <softgl/texture.h>
