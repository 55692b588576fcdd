#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/core/AllottedCpus.h>
#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>

#include <iostream>
#include <stdexcept>

int vslam::runTool(const std::string& tool, const std::string& usage, const std::function<int()>& body)
{
	useOnlyAllottedCpus();
	try
	{
		return body();
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << tool << ": error: " << e.what() << "\n" << usage;
		return 1;
	}
	catch (const ConfigError& e)
	{
		std::cerr << tool << ": error: configuration: " << e.what() << "\n";
		return 2;
	}
	catch (const InputError& e)
	{
		std::cerr << tool << ": error: " << e.what() << "\n";
		return 3;
	}
	catch (const std::exception& e)
	{
		std::cerr << tool << ": error: " << exceptionText(e) << "\n";
		return 4;
	}
}
